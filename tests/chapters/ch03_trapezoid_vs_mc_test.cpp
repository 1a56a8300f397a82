// Chapter 03 as a student runs it: a tiny study, its tables and summary, reproducibility
// across thread counts, and every kind of bad input.

#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "integration/integrands.hpp"
#include "io/plot.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch03_trapezoid_vs_mc";
// k up to 3, N up to 3000, 4 trials: about 2e5 evaluations, well under a second.
const std::string k_tiny = "--trials 4 --max-evaluations 3000 --dims 3,1,2 --quiet";

double closed_form(const std::string& integrand, int dims) {
  if (integrand == "gaussian_1d") return mcrt::Gaussian1D{}.reference();
  if (integrand == "ceil_sin_1d") return mcrt::CeilSinSquare1D{}.reference();
  if (integrand == "gaussian_kd") return mcrt::GaussianProduct{dims}.reference();
  if (integrand == "unit_ball_kd") return mcrt::UnitBallIndicator{dims}.reference();
  ADD_FAILURE() << "unknown integrand " << integrand;
  return 0.0;
}

TEST(Ch03Test, WritesErrorsSlopesSummaryAndPlots) {
  const auto dir = fresh_dir("ch03_smoke");
  const ProgramRun run = run_program(k_program, k_tiny + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());  // --quiet

  const CsvFile errors(dir / "errors.csv");
  EXPECT_EQ(errors.header(), (std::vector<std::string>{"integrand", "dims", "method",
                                                       "points_per_axis", "evaluations", "estimate",
                                                       "reference", "abs_error", "rmse"}));
  ASSERT_GT(errors.size(), 0u);
  std::map<std::string, int> rows_per_study;
  for (std::size_t r = 0; r < errors.size(); ++r) {
    ASSERT_EQ(errors.row(r).size(), errors.header().size()) << r;
    const std::string& integrand = errors.text(r, "integrand");
    const std::string& method = errors.text(r, "method");
    const int dims = static_cast<int>(errors.number(r, "dims"));
    const double evaluations = errors.number(r, "evaluations");
    rows_per_study[integrand + "/" + errors.text(r, "dims") + "/" + method]++;
    EXPECT_LE(evaluations, 3000.0);
    // The reference is the closed form, printed to round-trip exactly.
    EXPECT_EQ(errors.number(r, "reference"), closed_form(integrand, dims));
    // abs_error = |estimate - reference|, printed to 7 significant digits.
    const double abs_error = std::abs(errors.number(r, "estimate") - errors.number(r, "reference"));
    EXPECT_NEAR(errors.number(r, "abs_error"), abs_error, 1e-6 * abs_error);
    if (method == "trapezoid") {
      EXPECT_TRUE(errors.text(r, "rmse").empty());
      const double n = errors.number(r, "points_per_axis");
      EXPECT_EQ(evaluations, std::pow(n, dims));  // N = n^k
    } else {
      ASSERT_EQ(method, "monte_carlo");
      EXPECT_TRUE(errors.text(r, "points_per_axis").empty());
      // The rmse over trials is at least the error of their mean (Jensen), up to printing.
      EXPECT_GE(errors.number(r, "rmse") * (1.0 + 1e-5), errors.number(r, "abs_error"));
    }
  }
  // gaussian_1d, ceil_sin_1d, gaussian_kd at k = 1..3, unit_ball_kd at k = 2..3; two methods.
  EXPECT_EQ(rows_per_study.size(), 14u);
  for (const auto& [study, rows] : rows_per_study) EXPECT_GE(rows, 2) << study;  // a slope needs 2

  const CsvFile slopes(dir / "slopes.csv");
  EXPECT_EQ(slopes.header(),
            (std::vector<std::string>{"integrand", "dims", "method", "fitted_slope",
                                      "standard_error", "theory_slope", "points"}));
  ASSERT_EQ(slopes.size(), 14u);
  for (std::size_t r = 0; r < slopes.size(); ++r) {
    const std::string& integrand = slopes.text(r, "integrand");
    const std::string& method = slopes.text(r, "method");
    const double dims = slopes.number(r, "dims");
    const bool smooth = integrand.find("gaussian") == 0;
    const double theory = method == "monte_carlo" ? -0.5 : (smooth ? -2.0 : -1.0) / dims;
    EXPECT_NEAR(slopes.number(r, "theory_slope"), theory, 1e-6) << integrand << dims;
    const std::string key = integrand + "/" + slopes.text(r, "dims") + "/" + method;
    EXPECT_LE(slopes.number(r, "points"), rows_per_study[key]);
    if (integrand == "gaussian_1d" && method == "trapezoid") {
      // Deterministic: n = 2..3000. The error is c/(n-1)^2, so against log n the fit is a
      // little steeper than -2 (-2.06 here: the local slope is -2n/(n-1)); 0.15 allows that.
      EXPECT_NEAR(slopes.number(r, "fitted_slope"), -2.0, 0.15);
    }
    if (integrand == "gaussian_1d" && method == "monte_carlo") {
      // Random: 4 trials at 14 values of N give the slope a standard deviation near 0.06
      // (log of chi^2_4 / 4 has variance trigamma(2) = 0.64); 0.3 is five of them.
      EXPECT_NEAR(slopes.number(r, "fitted_slope"), -0.5, 0.3);
    }
  }

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["chapter"], "ch03_trapezoid_vs_mc");
  EXPECT_EQ(summary["trials"], 4);
  EXPECT_EQ(summary["dims"], nlohmann::json::parse("[1, 2, 3]"));  // sorted
  EXPECT_EQ(summary["max_evaluations"], 3000);
  ASSERT_EQ(summary["slopes"].size(), 14u);  // the same table as slopes.csv
  EXPECT_EQ(summary["slopes"][0]["integrand"], slopes.text(0, "integrand"));
  EXPECT_EQ(summary["slopes"][0]["points"], slopes.number(0, "points"));
  EXPECT_EQ(summary["flags"]["max-evaluations"], "3000");
  EXPECT_GT(summary["evaluations"].get<double>(), 0.0);

  // budget.csv: each k-dimensional study's last (largest) grid and N of errors.csv.
  const CsvFile budget(dir / "budget.csv");
  EXPECT_EQ(budget.header(),
            (std::vector<std::string>{"integrand", "dims", "reference", "points_per_axis",
                                      "trapezoid_evaluations", "trapezoid_error",
                                      "monte_carlo_evaluations", "monte_carlo_rmse"}));
  ASSERT_EQ(budget.size(), 5u);  // gaussian_kd at k = 1..3, unit_ball_kd at k = 2..3
  for (std::size_t b = 0; b < budget.size(); ++b) {
    const int dims = static_cast<int>(budget.number(b, "dims"));
    const double n = budget.number(b, "points_per_axis");
    EXPECT_EQ(budget.number(b, "reference"), closed_form(budget.text(b, "integrand"), dims));
    EXPECT_EQ(budget.number(b, "trapezoid_evaluations"), std::pow(n, dims));
    EXPECT_LE(std::pow(n, dims), 3000.0);  // the largest grid within the budget
    EXPECT_GT(std::pow(n + 1, dims), 3000.0);
    EXPECT_EQ(budget.number(b, "monte_carlo_evaluations"), 3000.0);
    for (std::size_t r = 0; r < errors.size(); ++r) {
      if (errors.text(r, "integrand") != budget.text(b, "integrand") ||
          errors.number(r, "dims") != dims)
        continue;
      if (errors.text(r, "method") == "trapezoid" && errors.number(r, "points_per_axis") == n) {
        EXPECT_EQ(errors.text(r, "abs_error"), budget.text(b, "trapezoid_error"));
      }
      if (errors.text(r, "method") == "monte_carlo" && errors.number(r, "evaluations") == 3000.0) {
        EXPECT_EQ(errors.text(r, "rmse"), budget.text(b, "monte_carlo_rmse"));
      }
    }
  }
  EXPECT_EQ(summary["at_budget"].size(), 5u);

  int expected_files = 6;  // errors.csv, slopes.csv, budget.csv, summary.json, timings.json,
                           // the manifest
  for (const char* plot :
       {"smooth_1d", "discontinuous_1d", "disk_2d", "slopes_vs_k", "error_at_budget_vs_k"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(plot) + ".gp"))) << plot;
    ++expected_files;
    if (mcrt::gnuplot_available()) {
      EXPECT_TRUE(std::filesystem::exists(dir / (std::string(plot) + ".png"))) << plot;
      EXPECT_TRUE(std::filesystem::exists(dir / (std::string(plot) + ".svg"))) << plot;
      expected_files += 2;
    }
  }
  EXPECT_EQ(file_count(dir), expected_files);  // no temporaries left behind
}

TEST(Ch03Test, PrintsTheSlopesTableAndHelp) {
  // --dims 1 alone: the disk (the ball at k = 2) is studied all the same.
  const auto dir = fresh_dir("ch03_table");
  const ProgramRun run =
      run_program(k_program, "--trials 2 --max-evaluations 100 --dims 1 --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The slopes table, one line per study and method.
  EXPECT_NE(run.out.find("fitted_slope"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("unit_ball_kd     2    trapezoid"), std::string::npos) << run.out;
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag :
       {"--trials", "--max-evaluations", "--dims", "--seed", "--threads", "--out", "--quiet"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

TEST(Ch03Test, SameSeedGivesIdenticalTablesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch03_threads1"), two = fresh_dir("ch03_threads2");
  const std::string flags = k_tiny + " --seed 5";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  // summary.json holds no timing, thread count or --out: the same file whatever --threads.
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  EXPECT_EQ(read_text(one / "errors.csv"), read_text(two / "errors.csv"));
  EXPECT_EQ(read_text(one / "slopes.csv"), read_text(two / "slopes.csv"));
  EXPECT_EQ(read_text(one / "budget.csv"), read_text(two / "budget.csv"));
  const auto other = fresh_dir("ch03_seed6");
  ASSERT_EQ(run_program(k_program, k_tiny + " --seed 6 --out " + other.string()).exit_code, 0);
  EXPECT_NE(read_text(one / "errors.csv"), read_text(other / "errors.csv"));  // Monte Carlo rows
}

class Ch03BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch03BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch03BadInputTest,
    ::testing::Values(
        BadInput{"--dims 0", "--dims"}, BadInput{"--dims 13", "--dims"},
        BadInput{"--dims two", "--dims"}, BadInput{"--dims 2,x", "--dims"},
        BadInput{"--max-evaluations 0", "--max-evaluations"},
        BadInput{"--max-evaluations -5", "--max-evaluations"},
        BadInput{"--max-evaluations 1e99x", "--max-evaluations"},
        BadInput{"--trials abc", "--trials"}, BadInput{"--trials 0", "--trials"},
        BadInput{"--trials 2.5", "--trials"}, BadInput{"--threads 0", "--threads"},
        // A grid over the budget: k = 8 needs 3^8 = 6561 evaluations for two grid sizes.
        BadInput{"--dims 8 --max-evaluations 1000", "6561"},
        BadInput{"--dims 8 --max-evaluations 1000", "--max-evaluations"},
        // Far too much work in all: refused at once, with the estimate.
        BadInput{"--trials 100000 --max-evaluations 1000000000", "--trials"},
        // Numbers are read as written: nothing clamped, no hex, no nan.
        BadInput{"--seed 18446744073709551616", "--seed"},
        BadInput{"--max-evaluations 0x100", "--max-evaluations"},
        BadInput{"--trials nan", "--trials"}, BadInput{"--dims 1,,2", "--dims"}),
    bad_input_name);

TEST(Ch03Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, k_tiny);
}

}  // namespace
