#include "app/summary.hpp"

#include "core/cpu_features.hpp"
#include "io/output.hpp"

namespace mcrt {

Json start_summary(std::string_view chapter, std::uint64_t seed) {
  return {{"chapter", chapter}, {"seed", seed}};
}

Json start_timings(std::string_view chapter, int threads) {
  return {{"chapter", chapter}, {"threads", threads}, {"cpu_avx2", cpu_has_avx2()}};
}

void write_json(const std::filesystem::path& path, const Json& json) {
  write_file_atomic(path, json.dump(2) + "\n");
}

void write_timings(const std::filesystem::path& dir, Json timings, const Json& run_flags) {
  timings["flags"] = run_flags;
  write_json(dir / "timings.json", timings);
}

}  // namespace mcrt
