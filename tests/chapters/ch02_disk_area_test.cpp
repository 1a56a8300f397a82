// Chapter 02 as a student runs it: a tiny study, its CSV tables and summary, reproducibility
// across thread counts, and every kind of bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "integration/ball.hpp"
#include "integration/disk_area.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch02_disk_area";
const std::string k_tiny = "--max-n 1000 --trials 20 --dims 2,3,7 --ball-n 1000 --points 50";

TEST(Ch02Test, WritesItsTablesPlotsAndSummary) {
  const auto dir = fresh_dir("ch02_smoke");
  const ProgramRun run = run_program(k_program, k_tiny + " --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());  // --quiet

  const auto header = [](const CsvFile& csv) {
    std::string text;
    for (const std::string& name : csv.header()) text += (text.empty() ? "" : ",") + name;
    return text;
  };
  const CsvFile disk(dir / "disk_area.csv");
  EXPECT_EQ(header(disk), "n,trials,mean_estimate,bias,empirical_std,theory_std,rmse");
  // log_grid(10, 1000, 4): 10, 18, 32, 56, 100, 178, 316, 562, 1000.
  ASSERT_EQ(disk.size(), 9u);
  EXPECT_EQ(disk.number(0, "n"), 10.0);
  EXPECT_EQ(disk.number(8, "n"), 1000.0);
  for (std::size_t r = 0; r < disk.size(); ++r) {
    const double mean = disk.number(r, "mean_estimate"), bias = disk.number(r, "bias");
    const double s = disk.number(r, "empirical_std"), rmse = disk.number(r, "rmse");
    EXPECT_EQ(disk.number(r, "trials"), 20.0);
    EXPECT_NEAR(bias, mean - mcrt::k_pi, 1e-8);  // bias = mean - pi (10 printed digits)
    EXPECT_NEAR(disk.number(r, "theory_std"),
                mcrt::disk_area_theory_std(static_cast<std::uint64_t>(disk.number(r, "n"))), 1e-9);
    // rmse^2 = (T-1)/T s^2 + bias^2 exactly, up to the printed digits.
    EXPECT_NEAR(rmse * rmse, 19.0 / 20.0 * s * s + bias * bias, 1e-8 + 1e-8 * rmse * rmse);
    // Every estimate 4 M / N lies in [0, 4].
    EXPECT_GE(mean, 0.0);
    EXPECT_LE(mean, 4.0);
  }

  const CsvFile ball(dir / "ball_volume.csv");
  EXPECT_EQ(header(ball),
            "k,n,trials,exact_volume,mean_estimate,empirical_std,theory_std,relative_std");
  ASSERT_EQ(ball.size(), 3u);
  const int dims[] = {2, 3, 7};
  for (std::size_t r = 0; r < 3; ++r) {
    const double exact = ball.number(r, "exact_volume"), theory = ball.number(r, "theory_std");
    EXPECT_EQ(ball.number(r, "k"), dims[r]);
    EXPECT_EQ(ball.number(r, "n"), 1000.0);
    EXPECT_NEAR(exact, mcrt::unit_ball_volume(dims[r]), 1e-8 * exact);
    EXPECT_NEAR(theory, mcrt::ball_volume_theory_std(dims[r], 1000), 1e-8 * theory);
    EXPECT_NEAR(ball.number(r, "relative_std"), theory / exact, 1e-8 * theory / exact);
  }

  const CsvFile ball_error(dir / "ball_error_vs_n.csv");
  EXPECT_EQ(header(ball_error),
            "k,n,trials,mean_estimate,empirical_std,theory_std,rmse,"
            "exact_volume,relative_theory_std,relative_rmse");
  ASSERT_EQ(ball_error.size(), 3u * 9u);                 // k = 2, 5, 10 on the grid 10..1000
  for (std::size_t r = 0; r < ball_error.size(); ++r) {  // the plot's relative errors
    const double exact = ball_error.number(r, "exact_volume");
    EXPECT_NEAR(exact, mcrt::unit_ball_volume(static_cast<int>(ball_error.number(r, "k"))),
                1e-8 * exact);
    EXPECT_NEAR(ball_error.number(r, "relative_rmse"), ball_error.number(r, "rmse") / exact,
                1e-6 * ball_error.number(r, "relative_rmse"));
    EXPECT_NEAR(ball_error.number(r, "relative_theory_std"),
                ball_error.number(r, "theory_std") / exact,
                1e-6 * ball_error.number(r, "relative_theory_std"));
  }

  const CsvFile points(dir / "points.csv");
  EXPECT_EQ(header(points), "x,y,inside");
  ASSERT_EQ(points.size(), 50u);
  int inside = 0;
  for (std::size_t r = 0; r < points.size(); ++r) {
    const double x = points.number(r, "x"), y = points.number(r, "y");
    // 6 digits: none on the edge.
    EXPECT_EQ(points.number(r, "inside"), x * x + y * y <= 1.0 ? 1.0 : 0.0);
    inside += points.number(r, "inside") > 0;
  }

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["picture"]["estimate"].get<double>(), 4.0 * inside / 50.0);
  EXPECT_EQ(summary["disk"]["theory_slope"], -0.5);
  EXPECT_TRUE(summary["disk"]["fitted_slope"].is_number());
  EXPECT_GT(read_json(dir / "timings.json")["disk"]["samples_per_second"].get<double>(), 0.0);
  EXPECT_EQ(summary["disk"]["samples"].get<double>(),
            20.0 * (10 + 18 + 32 + 56 + 100 + 178 + 316 + 562 + 1000));
  EXPECT_EQ(summary["ball"]["fitted_slopes"].size(), 3u);
  EXPECT_EQ(summary["ball"]["volumes"].size(), 3u);
  EXPECT_EQ(summary["ball"]["volumes"][1]["k"], 3);
  EXPECT_EQ(summary["seed"], 1);
  EXPECT_EQ(summary["flags"]["trials"], "20");
  for (const char* name : {"error_vs_n", "points", "ball_error_vs_n"})
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(name) + ".gp"))) << name;
}

TEST(Ch02Test, PrintsATableAndHelp) {
  const auto dir = fresh_dir("ch02_table");
  const ProgramRun run = run_program(k_program, k_tiny + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("slope of log(rmse)"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("samples per second"), std::string::npos);
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"--max-n", "--trials", "--dims", "--points", "--ball-n", "--seed",
                           "--threads", "--out", "--quiet"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

TEST(Ch02Test, SameSeedGivesIdenticalTablesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch02_threads1"), two = fresh_dir("ch02_threads2");
  const std::string flags = k_tiny + " --seed 5 --quiet";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  // summary.json holds no timing, thread count or --out: the same file whatever --threads.
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  for (const char* csv : {"disk_area.csv", "ball_volume.csv", "ball_error_vs_n.csv", "points.csv"})
    EXPECT_EQ(read_text(one / csv), read_text(two / csv)) << csv;
  const auto other = fresh_dir("ch02_seed6");
  ASSERT_EQ(run_program(k_program, k_tiny + " --seed 6 --quiet --out " + other.string()).exit_code,
            0);
  EXPECT_NE(read_text(one / "disk_area.csv"), read_text(other / "disk_area.csv"));
}

class Ch02BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch02BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch02BadInputTest,
    ::testing::Values(BadInput{"--max-n 0", "--max-n"}, BadInput{"--max-n ten", "--max-n"},
                      BadInput{"--max-n -5", "--max-n"}, BadInput{"--trials 1", "--trials"},
                      BadInput{"--trials 2.5", "--trials"}, BadInput{"--dims 0", "--dims"},
                      BadInput{"--dims 200", "--dims"}, BadInput{"--dims 2,x", "--dims"},
                      BadInput{"--points 0", "--points"}, BadInput{"--ball-n 1", "--ball-n"},
                      BadInput{"--threads 0", "--threads"}, BadInput{"--seed -1", "--seed"},
                      BadInput{"--frobnicate", "--frobnicate"},
                      // 1e12 x 1e5 trials: far too much work, refused with its estimate.
                      BadInput{"--max-n 1000000000000 --trials 100000", "--max-n"},
                      BadInput{"--ball-n 1000000000 --trials 1000 --dims 50", "--ball-n"},
                      // Numbers are read as written: nothing clamped, no hex, no exponent.
                      BadInput{"--seed 18446744073709551616", "--seed"},
                      BadInput{"--max-n 0x1000", "--max-n"}, BadInput{"--max-n 1e6", "--max-n"},
                      BadInput{"--trials ' 10'", "--trials"}, BadInput{"--dims 1,,2", "--dims"}),
    bad_input_name);

TEST(Ch02Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, k_tiny);
}

}  // namespace
