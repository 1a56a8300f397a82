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

void write_file_atomic(const fs::path& path, std::string_view bytes) {
  const fs::path temporary = temporary_path_for(path);  // new: never one planted under this name
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                        k_temporary_mode);
  std::error_code failure = fd < 0 ? std::error_code(errno, std::generic_category()) : write_all(fd, bytes);
  if (fd >= 0 && ::close(fd) != 0 && !failure) failure = {errno, std::generic_category()};
  if (failure) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw IoError("cannot write '" + path.string() + "': " + failure.message());
  }
  commit_file(temporary, path);
}

}  // namespace mcrt
