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

/// Writes `bytes` to a new temporary beside `path` (O_EXCL | O_NOFOLLOW, an unpredictable name),
/// then renames it over `path`: readers see the old file or the new one. Throws IoError naming
/// the file and the reason (a short write, a full disk, a failed close or rename), leaving nothing.
void write_file_atomic(const std::filesystem::path& path, std::string_view bytes);

/// A temporary name beside `path` (same folder, so rename() is atomic) that no one can guess:
/// `.<name>.tmp-<64 random bits>-<counter>`.
std::filesystem::path temporary_path_for(const std::filesystem::path& path);

/// Renames `from` over `to`; on failure removes `from` and throws IoError with the rename's reason.
void commit_file(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace mcrt
