#include "io/output.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "io/exclusive_file.hpp"

namespace mcrt {

namespace fs = std::filesystem;

void prepare_output_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    std::error_code ignored;
    const bool dangling = fs::is_symlink(fs::symlink_status(dir, ignored)) &&
                          !fs::exists(fs::status(dir, ignored));
    throw IoError("cannot create output folder '" + dir.string() + "': " +
                  (dangling ? std::string("it is a symbolic link to nothing (a dangling link)")
                   : ec     ? ec.message()
                            : std::string("a file of that name is in the way")));
  }
  if (::access(dir.c_str(), W_OK) != 0)
    throw IoError("cannot write to output folder '" + dir.string() + "': " +
                  std::strerror(errno));
}

fs::path temporary_path_for(const fs::path& path) {
  return path.parent_path() / std::string(".").append(path.filename().string()).append(".tmp-").append(random_suffix());
}

void commit_file(const fs::path& from, const fs::path& to) {
  std::error_code renamed;
  fs::rename(from, to, renamed);
  if (!renamed) return;
  std::error_code ignored;  // the rename's reason is the one to report
  fs::remove(from, ignored);
  throw IoError("cannot write '" + to.string() + "': " + renamed.message());
}

namespace {

// Writes all of `bytes` to a new file at `path` (never one planted under this name) and
// closes it; the system's reason otherwise.
std::error_code write_new_file(const fs::path& path, std::string_view bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                        k_temporary_mode);
  if (fd < 0) return {errno, std::generic_category()};
  std::error_code failure = write_all(fd, bytes);
  if (::close(fd) != 0 && !failure) failure = {errno, std::generic_category()};
  return failure;
}

}  // namespace

void write_file_atomic(const fs::path& path, std::string_view bytes) {
  const fs::path temporary = temporary_path_for(path);
  const std::error_code failure = write_new_file(temporary, bytes);
  if (failure) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw IoError("cannot write '" + path.string() + "': " + failure.message());
  }
  commit_file(temporary, path);
}

}  // namespace mcrt
