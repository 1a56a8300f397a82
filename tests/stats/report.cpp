#include "stats/report.hpp"

#include <atomic>
#include <cstdlib>
#include <system_error>

namespace mcrt::testing {

namespace fs = std::filesystem;

namespace {
std::atomic<bool> reports_enabled{true};
}

fs::path failure_report_root() {
  if (const char* dir = std::getenv("MCRT_TEST_REPORT_DIR"); dir && *dir) return dir;
  // Test executables live in <build>/bin/, so the report folder is <build>/test-reports/.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return fs::current_path() / "test-reports";
  return exe.parent_path().parent_path() / "test-reports";
}

void set_failure_reports(bool enabled) { reports_enabled = enabled; }
bool failure_reports_enabled() { return reports_enabled; }

}  // namespace mcrt::testing
