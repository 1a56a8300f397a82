#include "io/output.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <system_error>

#include <unistd.h>

namespace mcrt {

namespace fs = std::filesystem;

void prepare_output_dir(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw IoError("cannot create output folder '" + dir.string() + "': " +
                  (ec ? ec.message() : "a file of that name is in the way"));
  if (::access(dir.c_str(), W_OK) != 0)
    throw IoError("cannot write to output folder '" + dir.string() + "': " +
                  std::strerror(errno));
}

fs::path temporary_path_for(const fs::path& path) {
  static std::atomic<unsigned> counter{0};
  return path.parent_path() / ("." + path.filename().string() + ".tmp-" +
                               std::to_string(::getpid()) + "-" + std::to_string(counter++));
}

void commit_file(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    fs::remove(from, ec);
    throw IoError("cannot write '" + to.string() + "': " + ec.message());
  }
}

void write_file_atomic(const fs::path& path, std::string_view bytes) {
  const fs::path temporary = temporary_path_for(path);
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    if (!file) throw IoError("cannot write '" + path.string() + "': " + std::strerror(errno));
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.close();
    if (!file) {
      std::error_code ec;
      fs::remove(temporary, ec);
      throw IoError("cannot write '" + path.string() + "': write failed (disk full?)");
    }
  }
  commit_file(temporary, path);
}

}  // namespace mcrt
