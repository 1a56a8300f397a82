#pragma once
// Where failing statistical tests leave their evidence (CSV tables, gnuplot plots), so a
// student can open the files and see where a sampler or estimator is wrong.

#include <filesystem>

namespace mcrt::testing {

/// The folder failure reports go to: $MCRT_TEST_REPORT_DIR when set, else `test-reports/`
/// in the build tree (beside the bin/ folder that holds the running test executable).
std::filesystem::path failure_report_root();

/// Turns failure reports on or off for this process. They are on by default; the calibration
/// run turns them off, since it provokes thousands of designed failures on purpose.
void set_failure_reports(bool enabled);
bool failure_reports_enabled();

}  // namespace mcrt::testing
