// Chapter 04 as a student runs it: a tiny sweep and its tables, exact ray counts in the
// furnace, reproducibility across thread counts, the --max-rays refusal and bad input.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "render/recursive_estimator.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch04_recursive_nk";
// 8 x 6 pixels, N = 1 and 2, k = 0..2; equal cost at depth 1 with 6 rays per pixel, which
// buys N = 1 three samples (2 rays each) and N = 2 two samples (3 rays each); the grid's top
// row at 4 spp.
const std::string k_tiny =
    "--width 8 --height 6 --spp 1 --branching 2,1 --max-depth 2 "
    "--equal-cost-depth 1 --budget 6 --grid-spp 4 --quiet";
constexpr std::uint64_t k_pixels = 8 * 6;

// The header row of a CSV file, as written.
std::string header(const CsvFile& csv) {
  std::string text;
  for (const std::string& name : csv.header()) text += (text.empty() ? "" : ",") + name;
  return text;
}

TEST(Ch04Test, TinySweepWritesItsTablesPlotsAndSummary) {
  const auto dir = fresh_dir("ch04_smoke");
  const ProgramRun run = run_program(k_program, k_tiny + " --seed 3 --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());  // --quiet

  const CsvFile rays(dir / "rays.csv");
  EXPECT_EQ(header(rays),
            "branching,depth,rays,predicted_max_rays,seconds,rays_per_second,mean_radiance");
  ASSERT_EQ(rays.size(), 2u * 3);  // N = 1, 2 (sorted), k = 0, 1, 2
  double previous_n1_mean = -1.0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const int n = std::stoi(rays.text(i, "branching")), k = std::stoi(rays.text(i, "depth"));
    EXPECT_EQ(n, i < 3 ? 1 : 2);
    EXPECT_EQ(k, static_cast<int>(i % 3));
    const std::uint64_t traced = std::stoull(rays.text(i, "rays"));
    const std::uint64_t predicted = std::stoull(rays.text(i, "predicted_max_rays"));
    EXPECT_EQ(predicted, k_pixels * mcrt::max_rays_per_sample(n, k));
    EXPECT_LE(traced, predicted);
    if (k == 0) {
      EXPECT_EQ(traced, k_pixels);  // one camera ray per pixel, counted even if it escapes
    }
    EXPECT_GE(rays.number(i, "seconds"), 0.0);
    const double mean = rays.number(i, "mean_radiance");
    EXPECT_TRUE(std::isfinite(mean) && mean >= 0.0) << rays.text(i, "mean_radiance");
    if (n == 1) {  // N = 1: one bounce deeper extends the same paths, so never darker
      EXPECT_GE(mean, previous_n1_mean);
      previous_n1_mean = mean;
    }
  }

  const CsvFile equal_cost(dir / "equal_cost.csv");
  EXPECT_EQ(header(equal_cost),
            "branching,depth,spp,predicted_rays_per_pixel,rays_per_pixel,seconds,mean_radiance,"
            "rms_error,relative_rms_error,rms_error_at_budget");
  ASSERT_EQ(equal_cost.size(), 2u);
  for (std::size_t i = 0; i < equal_cost.size(); ++i) {
    const int n = std::stoi(equal_cost.text(i, "branching"));
    const int spp = std::stoi(equal_cost.text(i, "spp"));
    EXPECT_EQ(equal_cost.text(i, "depth"), "1");
    EXPECT_EQ(spp, n == 1 ? 3 : 2);  // floor(6 / (1 + N))
    EXPECT_EQ(std::stoull(equal_cost.text(i, "predicted_rays_per_pixel")),
              spp * mcrt::max_rays_per_sample(n, 1));
    EXPECT_LE(equal_cost.number(i, "rays_per_pixel"), 6.0);
    EXPECT_GE(equal_cost.number(i, "rms_error"), 0.0);
    EXPECT_TRUE(std::isfinite(equal_cost.number(i, "rms_error_at_budget")));
  }

  const CsvFile missing(dir / "missing_light.csv");
  EXPECT_EQ(header(missing), "depth,mean_radiance,limit_mean_radiance,missing_fraction");
  ASSERT_EQ(missing.size(), 3u);
  const std::vector<double> missing_fraction = missing.numbers("missing_fraction");
  for (std::size_t i = 1; i < missing_fraction.size(); ++i)  // less missing one bounce deeper
    EXPECT_LE(missing_fraction[i], missing_fraction[i - 1]);

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["chapter"], "ch04_recursive_nk");
  EXPECT_EQ(summary["seed"], 3);
  EXPECT_EQ(summary["sweep"].size(), 6u);
  EXPECT_EQ(summary["non_finite_samples"], 0);
  EXPECT_LE(summary["rays"].get<double>(), summary["predicted_max_rays"].get<double>());
  const int best = summary["equal_cost"]["best_branching"];
  EXPECT_TRUE(best == 1 || best == 2);
  EXPECT_FALSE(summary["equal_cost"]["conclusion"].get<std::string>().empty());
  EXPECT_EQ(summary["flags"]["max-depth"], "2");
  EXPECT_EQ(summary["grid"]["top_row_spp"], 4);
  EXPECT_EQ(summary["grid"]["bottom_row_rays_per_pixel"], 6);
  for (const char* file : {"grid.png", "rays_vs_depth.gp", "mean_radiance_vs_depth.gp",
                           "missing_light_vs_depth.gp", "equal_cost.gp"})
    EXPECT_TRUE(std::filesystem::exists(dir / file)) << file;
}

// No ray leaves the furnace: every count is the prediction, exactly.
TEST(Ch04Test, FurnaceRayCountsEqualThePrediction) {
  const auto dir = fresh_dir("ch04_furnace");
  std::string flags = k_tiny;
  flags.replace(flags.find("--branching 2,1"), 15, "--branching 1,3");
  const ProgramRun run =
      run_program(k_program, flags + " --scene furnace --albedo 0.6 --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CsvFile rays(dir / "rays.csv");
  ASSERT_EQ(rays.size(), 6u);
  for (std::size_t i = 0; i < rays.size(); ++i)
    EXPECT_EQ(rays.text(i, "rays"), rays.text(i, "predicted_max_rays"));
  // The missing light's guide is a^(k+1) with the furnace's albedo, not a fitted one.
  EXPECT_NE(read_text(dir / "missing_light_vs_depth.gp").find("a = 0.6\n"), std::string::npos);
}

TEST(Ch04Test, PrintsATableAConclusionAndHelp) {
  const auto dir = fresh_dir("ch04_table");
  std::string flags = k_tiny;
  flags.erase(flags.find(" --quiet"));
  const ProgramRun run = run_program(k_program, flags + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("predicted"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("At equal cost"), std::string::npos) << run.out;
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag :
       {"--branching", "--max-depth", "--max-rays", "--spp", "--budget", "--equal-cost-depth",
        "--grid-spp", "--scene", "--seed", "--threads", "--out"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

TEST(Ch04Test, SameSeedSameOutputsWhateverTheThreadCount) {
  const auto one = fresh_dir("ch04_threads1"), two = fresh_dir("ch04_threads2");
  const std::string flags = k_tiny + " --seed 12";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  // summary.json holds no timing, thread count or --out: the same file whatever --threads.
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  const std::vector<std::string> rays_timings{"seconds", "rays_per_second"};
  EXPECT_EQ(CsvFile(one / "rays.csv").without(rays_timings),
            CsvFile(two / "rays.csv").without(rays_timings));
  EXPECT_EQ(CsvFile(one / "equal_cost.csv").without({"seconds"}),
            CsvFile(two / "equal_cost.csv").without({"seconds"}));
  EXPECT_EQ(read_text(one / "missing_light.csv"), read_text(two / "missing_light.csv"));
  EXPECT_EQ(read_text(one / "grid.png"), read_text(two / "grid.png"));
  const auto other = fresh_dir("ch04_seed13");
  ASSERT_EQ(run_program(k_program, k_tiny + " --seed 13 --out " + other.string()).exit_code, 0);
  EXPECT_NE(read_text(one / "missing_light.csv"), read_text(other / "missing_light.csv"));
}

// N = 8 to depth 14 at the default image size is ~6e16 rays, decades of work: a run that
// started it would never return. The refusal names the flag, the predicted count and the time.
TEST(Ch04Test, RefusesTooManyRaysBeforeAnyWork) {
  const auto dir = fresh_dir("ch04_refused");
  const auto out = dir / "out";
  const ProgramRun run =
      run_program(k_program, "--branching 8 --max-depth 14 --out " + out.string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
  EXPECT_NE(run.err.find("--max-rays"), std::string::npos) << run.err;
  const std::size_t count_at = run.err.find("about ");
  ASSERT_NE(count_at, std::string::npos) << run.err;
  EXPECT_GT(std::stod(run.err.substr(count_at + 6)), 1e16) << run.err;  // the predicted count
  const std::size_t time_at = run.err.find("(~");
  ASSERT_NE(time_at, std::string::npos) << run.err;
  EXPECT_GT(std::stod(run.err.substr(time_at + 2)), 100.0) << run.err;  // how long it would take
  EXPECT_NE(run.err.find(" years on "), std::string::npos) << run.err;
  EXPECT_FALSE(std::filesystem::exists(out));  // refused before creating any output

  // The limit is the flag's value: the tiny run is refused under a limit of 100 rays.
  const ProgramRun tight = run_program(k_program, k_tiny + " --max-rays 100 --out " + out.string());
  EXPECT_EQ(tight.exit_code, 2);
  EXPECT_NE(tight.err.find("--max-rays"), std::string::npos) << tight.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

class Ch04BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch04BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch04BadInputTest,
    ::testing::Values(
        BadInput{"--branching 0", "--branching"}, BadInput{"--branching 1,0,2", "--branching"},
        BadInput{"--branching two", "--branching"}, BadInput{"--branching 1.5", "--branching"},
        BadInput{"--max-depth -1", "--max-depth"}, BadInput{"--max-depth three", "--max-depth"},
        BadInput{"--max-depth 65", "--max-depth"}, BadInput{"--max-rays lots", "--max-rays"},
        BadInput{"--max-rays 0", "--max-rays"}, BadInput{"--spp abc", "--spp"},
        BadInput{"--spp 0", "--spp"}, BadInput{"--budget x", "--budget"},
        BadInput{"--budget 3 --equal-cost-depth 3", "--budget"},
        BadInput{"--equal-cost-depth -2", "--equal-cost-depth"},
        BadInput{"--grid-spp 0", "--grid-spp"}, BadInput{"--width 0", "--width"},
        BadInput{"--scene moon", "--scene"}, BadInput{"--threads 0", "--threads"},
        // Numbers are read as written: a nan limit no longer lets 1e27 rays start.
        BadInput{"--max-rays nan --max-depth 30 --branching 8", "--max-rays"},
        BadInput{"--max-rays inf", "--max-rays"}, BadInput{"--max-rays 1e16", "--max-rays"},
        BadInput{"--spp 0x10", "--spp"}, BadInput{"--albedo nan", "--albedo"},
        BadInput{"--seed 18446744073709551616", "--seed"}),
    bad_input_name);

TEST(Ch04Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, k_tiny);
}

}  // namespace
