#pragma once
/// summary.json: a run's key figures, seed and flags, byte for byte the same whatever
/// --threads. timings.json: what depends on the machine (seconds, rates, threads, CPU features)
/// and the flags that change no result.

#include <cstdint>
#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

namespace mcrt {

using Json = nlohmann::ordered_json;  ///< keeps keys in the order they were written

/// The opening entries of every chapter's summary: its name and seed.
Json start_summary(std::string_view chapter, std::uint64_t seed);

/// The opening entries of every chapter's timings.json: its name, threads and AVX2.
Json start_timings(std::string_view chapter, int threads);

/// Writes `json` pretty-printed to `path` (write_file_atomic).
void write_json(const std::filesystem::path& path, const Json& json);

/// Ends `timings` with the run's own flags (app/cli.hpp's run_flags_json) and writes it as
/// dir/timings.json.
void write_timings(const std::filesystem::path& dir, Json timings, const Json& run_flags);

}  // namespace mcrt
