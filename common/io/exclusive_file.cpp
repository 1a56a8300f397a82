#include "io/exclusive_file.hpp"

#include <cerrno>
#include <cstdint>
#include <random>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

namespace mcrt {

std::string random_suffix() {
  std::random_device source;  // getrandom(2) in libstdc++
  const std::uint64_t bits = (std::uint64_t{source()} << 32) | source();
  return fmt::format("{:016x}", bits);
}

NewFile create_temporary(int dir_fd, const std::filesystem::path& beside) {
  NewFile file;
  // 64 random bits: a name already taken is someone's plant or a one-in-2^64 draw; a few
  // tries are plenty for the second, and the first is never opened.
  for (int attempt = 0; attempt < 8; ++attempt) {
    const auto name = fmt::format(".{}.tmp-{}", beside.filename().string(), random_suffix());
    file.name = (beside.parent_path() / name).string();
    file.fd = ::openat(dir_fd, file.name.c_str(),
                       O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, k_temporary_mode);
    file.error = {file.fd < 0 ? errno : 0, std::generic_category()};
    if (file.fd < 0 && errno != EEXIST) break;
    if (file.fd < 0) continue;
    ::flock(file.fd, LOCK_EX);  // held until closed: the mark of a live writer
    // A cleaner may have taken the lock first, between the open and the flock, and removed
    // the name: then this file is nobody's, and another is made.
    struct stat status {};
    if (::fstat(file.fd, &status) == 0 && status.st_nlink > 0) return file;
    ::close(file.fd);
    file.fd = -1;
    file.error = std::make_error_code(std::errc::no_such_file_or_directory);
  }
  return file;
}

std::error_code write_all(int fd, std::string_view bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return {errno, std::generic_category()};
    if (n == 0) return std::make_error_code(std::errc::no_space_on_device);
    written += static_cast<std::size_t>(n);
  }
  return {};
}

std::size_t read_all(int fd, std::string& bytes) {
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  return got;
}

}  // namespace mcrt
