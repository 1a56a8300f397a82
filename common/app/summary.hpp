#pragma once
/// summary.json and timings.json. summary.json holds a run's key figures, the seed and the
/// flags that decide them: the same seed and flags give the same file byte for byte, whatever
/// --threads. timings.json holds what depends on the machine and the moment: seconds, rates,
/// the thread count, the CPU's features and the flags that change no result (--threads,
/// --out, --quiet).

#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/cli.hpp"

namespace mcrt {

using Json = nlohmann::ordered_json;  ///< keeps keys in the order they were written

/// The opening entries of every chapter's summary: its name and seed.
Json start_summary(const Chapter& chapter, const CommonOptions& common);

/// The opening entries of every chapter's timings.json: its name, the thread count and
/// whether the processor has AVX2 (the fast engines' path).
Json start_timings(const Chapter& chapter, const CommonOptions& common);

/// Writes `json` pretty-printed to `path` (temporary file, then rename). Throws IoError.
void write_json(const std::filesystem::path& path, const Json& json);

/// Ends `timings` with the run's own flags (run_flags_json) and writes it as dir/timings.json.
void write_timings(const std::filesystem::path& dir, Json timings, const CLI::App& app);

}  // namespace mcrt
