#include "app/summary.hpp"

#include "core/cpu_features.hpp"
#include "io/output.hpp"

namespace mcrt {

Json start_summary(const Chapter& chapter, const CommonOptions& common) {
  Json summary;
  summary["chapter"] = chapter.name;
  summary["seed"] = common.seed;
  return summary;
}

Json start_timings(const Chapter& chapter, const CommonOptions& common) {
  Json timings;
  timings["chapter"] = chapter.name;
  timings["threads"] = common.threads;
  timings["cpu_avx2"] = cpu_has_avx2();
  return timings;
}

void write_json(const std::filesystem::path& path, const Json& json) {
  write_file_atomic(path, json.dump(2) + "\n");
}

void write_timings(const std::filesystem::path& dir, Json timings, const CLI::App& app) {
  timings["flags"] = run_flags_json(app);
  write_json(dir / "timings.json", timings);
}

}  // namespace mcrt
