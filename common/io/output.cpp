#include "io/output.hpp"

#include <cerrno>
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
    const bool dangling =
        fs::is_symlink(fs::symlink_status(dir, ignored)) && !fs::exists(fs::status(dir, ignored));
    throw IoError("cannot create output folder '" + dir.string() + "': " +
                  (dangling ? std::string("it is a symbolic link to nothing (a dangling link)")
                   : ec     ? ec.message()
                            : std::string("a file of that name is in the way")));
  }
  if (::access(dir.c_str(), W_OK) != 0)
    throw IoError("cannot write to output folder '" + dir.string() + "': " + std::strerror(errno));
}

void write_file_atomic(const fs::path& path, std::string_view bytes) {
  const NewFile file = create_temporary(AT_FDCWD, path);  // new: never one planted there
  std::error_code failure = file.fd < 0 ? file.error : write_all(file.fd, bytes);
  if (file.fd >= 0 && ::close(file.fd) != 0 && !failure) failure = {errno, std::generic_category()};
  if (!failure && ::rename(file.name.c_str(), path.c_str()) != 0)
    failure = {errno, std::generic_category()};
  if (failure && file.fd >= 0) ::unlink(file.name.c_str());  // ours: made O_EXCL
  if (failure) throw IoError("cannot write '" + path.string() + "': " + failure.message());
}

}  // namespace mcrt
