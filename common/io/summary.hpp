#pragma once
/// summary.json: each chapter's key figures, the seed and the flags, written atomically.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "io/cli.hpp"

namespace mcrt {

using Json = nlohmann::ordered_json;  ///< keeps keys in the order they were written

/// The opening entries of every chapter's summary: its name, seed and thread count.
Json start_summary(const Chapter& chapter, const CommonOptions& common);

/// Writes `json` pretty-printed to `path` (temporary file, then rename). Throws IoError.
void write_json(const std::filesystem::path& path, const Json& json);

}  // namespace mcrt
