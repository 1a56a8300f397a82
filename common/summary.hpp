#pragma once
/// summary.json: each chapter's key figures, the seed and the flags, written atomically.

#include <filesystem>

#include <nlohmann/json.hpp>

namespace mcrt {

using Json = nlohmann::ordered_json;  ///< keeps keys in the order they were written

/// Writes `json` pretty-printed to `path` (temporary file, then rename). Throws IoError.
void write_json(const std::filesystem::path& path, const Json& json);

}  // namespace mcrt
