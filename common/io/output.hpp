#pragma once
/// Atomic file writes: every file appears whole or not at all. (A chapter's output folder as
/// a whole: app/run_folder.hpp.)

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace mcrt {

/// An input/output failure: the chapter exits with code 1 and this message.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Creates `dir` (and its parents) and checks that files can be written in it, for tools that
/// write into a folder of their own (a chapter's run uses RunFolder instead). Throws IoError
/// naming the folder otherwise.
void prepare_output_dir(const std::filesystem::path& dir);

/// Writes `bytes` to a new temporary beside `path` (io/exclusive_file.hpp), then renames it
/// over `path`: readers see the old file or the new one. Throws IoError naming
/// the file and the reason (a short write, a full disk, a failed close or rename), leaving nothing.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

}  // namespace mcrt
