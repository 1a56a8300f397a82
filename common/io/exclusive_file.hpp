#pragma once
/// Files created, never reused: every temporary is made O_CREAT|O_EXCL|O_NOFOLLOW under a name
/// nobody can predict, so a link or file planted under that name is never written through.

#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

namespace mcrt {

/// Sixteen hexadecimal digits from the system's random source: 64 bits nobody can guess.
std::string random_suffix();

/// The mode of every temporary file: readable by others, writable by its owner only.
inline constexpr unsigned k_temporary_mode = 0644;

/// A temporary file this process created, open for writing.
struct NewFile {
  int fd = -1;       ///< -1 when it could not be created
  std::string name;  ///< its name inside the folder it was created in
  std::error_code error;
};

/// Creates `.<name>.tmp-<random_suffix()>` beside `beside` (relative to the folder open as
/// `dir_fd`, or AT_FDCWD) and locks it (flock): a lock nobody holds marks the file of a writer
/// that died (the reference cache's clean-up).
NewFile create_temporary(int dir_fd, const std::filesystem::path& beside);

/// Writes all of `bytes` to `fd`; the system's reason on failure (a write of nothing: a full disk).
std::error_code write_all(int fd, std::string_view bytes);

/// Reads into `bytes` until it is full or the file ends; returns how many bytes it got.
std::size_t read_all(int fd, std::string& bytes);

}  // namespace mcrt
