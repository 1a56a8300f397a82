#include "io/summary.hpp"

#include "io/output.hpp"

namespace mcrt {

Json start_summary(const Chapter& chapter, const CommonOptions& common) {
  Json summary;
  summary["chapter"] = chapter.name;
  summary["seed"] = common.seed;
  summary["threads"] = common.threads;
  return summary;
}

void write_json(const std::filesystem::path& path, const Json& json) {
  write_file_atomic(path, json.dump(2) + "\n");
}

}  // namespace mcrt
