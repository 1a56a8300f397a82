#pragma once
// Folders and files for the tests that write them: a fresh folder per test, whole files read
// and written, a folder's entries counted.

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>

#include <unistd.h>

namespace mcrt::testing {

/// The suites' folders of this process, removed when it exits normally (a death test's child
/// leaves by _exit, so the folders its parent still reads stay).
class TempSuiteDirs {
 public:
  void add(const std::filesystem::path& dir) { dirs_.insert(dir); }
  ~TempSuiteDirs() {
    std::error_code ignored;  // a folder already gone is fine
    for (const std::filesystem::path& dir : dirs_) std::filesystem::remove_all(dir, ignored);
  }

 private:
  std::set<std::filesystem::path> dirs_;
};
inline TempSuiteDirs temp_suite_dirs;

/// `suite`'s own folder under the system's temporary folder (mcrt_<suite>_<pid>), created if
/// need be and removed when the process exits.
inline std::filesystem::path temp_suite_dir(const std::string& suite) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("mcrt_" + suite + "_" + std::to_string(::getpid()));
  temp_suite_dirs.add(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// An empty folder `name` in `suite`'s own, emptied if a previous test left it.
inline std::filesystem::path fresh_temp_dir(const std::string& suite, const std::string& name) {
  const std::filesystem::path dir = temp_suite_dir(suite) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// The whole file, bytes as they are ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream s;
  s << file.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

/// How many files and folders `dir` holds (not counting theirs).
inline int entries(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace mcrt::testing
