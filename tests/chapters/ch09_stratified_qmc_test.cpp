// Chapter 09 as a student runs it: a tiny run's tables, summary and plots; the fitted slopes
// of a larger run within their predicted bands; the same bytes whatever --threads; and every
// kind of bad input.

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <boost/math/special_functions/trigamma.hpp>
#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "integration/integrands.hpp"
#include "integration/point_set_rates.hpp"
#include "io/plot.hpp"
#include "stats/hypothesis.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch09_stratified_qmc";
// N = 16 ... 256, 4 randomisations, the dimension study at k = 1, 2, 3 with N = 256: about
// 1e5 points, well under a second.
const std::string k_tiny =
    "--trials 4 --max-n 256 --budget 256 --dims 3,1,2 --picture-points 16 --quiet";
const std::vector<std::string> k_samplers = {"independent", "jittered",   "latin_hypercube",
                                             "sobol_xor",   "sobol_owen", "halton"};

TEST(Ch09Test, WritesTablesSummaryAndPlots) {
  const auto dir = fresh_dir("ch09_smoke");
  const ProgramRun run = run_program(k_program, k_tiny + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());  // --quiet

  const std::vector<std::string> error_header = {"sampler",       "n",    "trials",
                                                 "mean_estimate", "rmse", "theory_line"};
  const double pi = mcrt::UnitBallIndicator{2}.reference();
  const mcrt::GaussianProduct bump{2};
  for (const char* study : {"disk", "smooth"}) {
    const CsvFile errors(dir / (std::string(study) + ".csv"));
    EXPECT_EQ(errors.header(), error_header);
    std::map<std::string, std::vector<double>> sizes;
    for (std::size_t r = 0; r < errors.size(); ++r) {
      sizes[errors.text(r, "sampler")].push_back(errors.number(r, "n"));
      EXPECT_EQ(errors.number(r, "trials"), 4.0);
      EXPECT_GT(errors.number(r, "rmse"), 0.0);
      // The mean of 4 unbiased estimates: within 10 rms errors of I (a loose sanity bound;
      // unbiasedness itself is tested in tests/sampling/point_sets_test.cpp).
      const double exact = std::string(study) == "disk" ? pi : bump.reference();
      EXPECT_LT(std::abs(errors.number(r, "mean_estimate") - exact), 10 * errors.number(r, "rmse"));
      if (errors.text(r, "sampler") == "independent") {  // the exact sigma / sqrt(N)
        const double variance =
            std::string(study) == "disk"
                ? 4.0 * pi - pi * pi
                : bump.integral_of_square() - bump.reference() * bump.reference();
        EXPECT_NEAR(errors.number(r, "theory_line"), std::sqrt(variance / errors.number(r, "n")),
                    1e-5 * errors.number(r, "theory_line"));  // printed to 7 digits
      }
    }
    for (const std::string& sampler : k_samplers)
      EXPECT_EQ(sizes[sampler], (std::vector<double>{16, 32, 64, 128, 256})) << study << sampler;
    if (std::string(study) == "smooth") {  // round(2^(m + 1/2)) made odd
      EXPECT_EQ(sizes["sobol_owen_odd_n"], (std::vector<double>{23, 45, 91, 181}));
    }
    EXPECT_EQ(sizes.size(), std::string(study) == "disk" ? 6u : 7u);
  }

  const CsvFile slopes(dir / "slopes.csv");
  EXPECT_EQ(slopes.header(),
            (std::vector<std::string>{"study", "sampler", "fitted_slope", "standard_error",
                                      "predicted_slope", "points"}));
  ASSERT_EQ(slopes.size(), 13u);
  for (std::size_t r = 0; r < slopes.size(); ++r)
    EXPECT_EQ(slopes.number(r, "predicted_slope"),
              rate_band(slopes.text(r, "study"), slopes.text(r, "sampler")).predicted)
        << slopes.text(r, "study") << "/" << slopes.text(r, "sampler");

  // dimension.csv: per method, a row per k; the trapezoid rule on floor(256^(1/k)) per axis.
  const CsvFile dimension(dir / "dimension.csv");
  EXPECT_EQ(dimension.header(),
            (std::vector<std::string>{"dims", "method", "evaluations", "points_per_axis",
                                      "mean_estimate", "reference", "rmse", "relative_error",
                                      "theory_rmse"}));
  ASSERT_EQ(dimension.size(), 12u);
  std::map<std::string, std::vector<double>> ks;
  for (std::size_t r = 0; r < dimension.size(); ++r) {
    const int k = static_cast<int>(dimension.number(r, "dims"));
    ks[dimension.text(r, "method")].push_back(k);
    EXPECT_EQ(dimension.number(r, "reference"), mcrt::GaussianProduct{k}.reference());
    if (dimension.text(r, "method") == "trapezoid") {
      const double n = dimension.number(r, "points_per_axis");
      EXPECT_EQ(n, std::vector<double>({256, 16, 6})[static_cast<std::size_t>(k - 1)]);
      EXPECT_EQ(dimension.number(r, "evaluations"), std::pow(n, k));
    } else {
      EXPECT_EQ(dimension.number(r, "evaluations"), 256.0);
    }
  }
  for (const char* method : {"independent", "latin_hypercube", "sobol_owen", "trapezoid"})
    EXPECT_EQ(ks[method], (std::vector<double>{1, 2, 3})) << method;

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["chapter"], k_program);
  EXPECT_EQ(summary["trials"], 4);
  EXPECT_EQ(summary["dims"], nlohmann::json::parse("[1, 2, 3]"));  // sorted
  EXPECT_EQ(summary["disk"].size(), 6u);
  EXPECT_EQ(summary["smooth"].size(), 7u);
  EXPECT_EQ(summary["smooth"]["sobol_owen"]["predicted_slope"], -1.5);
  EXPECT_EQ(summary["dimension"]["gain_over_independent"].size(), 3u);
  EXPECT_EQ(summary["flags"]["max-n"], "256");

  int expected_files = 8;  // 5 CSV files, summary.json, timings.json, the manifest
  for (const char* plot :
       {"disk_error_vs_n", "smooth_error_vs_n", "error_vs_dimension", "point_sets"}) {
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

TEST(Ch09Test, FittedSlopesLieInTheirPredictedBands) {
  // R = 32 randomisations at N = 16 ... 4096, as the rate checks of
  // tests/integration/point_set_rates_checks.cpp: each slope within its band's allowance plus
  // z noise standard deviations (point_set_rates.hpp), z for a two-sided 1e-4. The checks'
  // calibration (300 seeds each, no rejection) stands for these 13 slopes too: at most 1.3e-3
  // for the test, at its one seed.
  const auto dir = fresh_dir("ch09_slopes");
  const ProgramRun run =
      run_program(k_program,
                  "--trials 32 --max-n 4096 --budget 16 --dims 1 --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const double z_limit = normal_quantile(1.0 - 1e-4 / 2);
  const CsvFile slopes(dir / "slopes.csv");
  ASSERT_EQ(slopes.size(), 13u);
  for (std::size_t r = 0; r < slopes.size(); ++r) {
    const std::string study = slopes.text(r, "study"), sampler = slopes.text(r, "sampler");
    // Sxx of the series' log N: 9 powers of two, or the 8 odd sizes between them (the same
    // spacing, ln 2, so the same Sxx shifted by half a step: sum (m - mean)^2 ln^2 2).
    const double points = slopes.number(r, "points");
    EXPECT_EQ(points, sampler == "sobol_owen_odd_n" ? 8.0 : 9.0);
    const double sxx = (points * points - 1.0) * points / 12.0 * std::log(2.0) * std::log(2.0);
    const double noise_sd = std::sqrt(boost::math::trigamma(16.0) / 4.0 / sxx);
    const double z = excess_over_allowance(slopes.number(r, "fitted_slope"), noise_sd,
                                           rate_band(study, sampler));
    EXPECT_LT(z, z_limit) << study << "/" << sampler << ": slope "
                          << slopes.number(r, "fitted_slope");
  }
}

TEST(Ch09Test, PrintsTheSlopesTableAndHelp) {
  const auto dir = fresh_dir("ch09_table");
  const ProgramRun run =
      run_program(k_program, "--trials 2 --max-n 64 --budget 16 --dims 2 --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("fitted_slope"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("sobol_owen_odd_n"), std::string::npos) << run.out;
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag :
       {"--trials", "--max-n", "--budget", "--dims", "--picture-points", "--seed", "--threads",
        "--out", "--quiet", "--sampler", "--render-max-spp", "--render-scene", "--reference-dir"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

TEST(Ch09Test, SameSeedGivesIdenticalFilesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch09_threads1"), two = fresh_dir("ch09_threads3");
  const std::string flags = k_tiny + " --seed 5";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 3 --out " + two.string()).exit_code, 0);
  // Every file but timings.json: the tables, summary.json, the plots' scripts and images.
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(one)) {
    const std::string name = entry.path().filename().string();
    if (name == "timings.json") continue;
    EXPECT_EQ(read_text(entry.path()), read_text(two / name)) << name;
    ++compared;
  }
  EXPECT_GE(compared, 10);
  const auto other = fresh_dir("ch09_seed6");
  ASSERT_EQ(run_program(k_program, k_tiny + " --seed 6 --out " + other.string()).exit_code, 0);
  EXPECT_NE(read_text(one / "disk.csv"), read_text(other / "disk.csv"));
}

// The render study, tiny: chapter 05's path tracer with each sampler at spp 1, 2, 4, 8 and
// depths 1 and 3, against references cached in a folder of the test's own; the same files
// whatever --threads.
const std::string k_render =
    "--trials 2 --max-n 64 --budget 16 --dims 2 --picture-points 4 --quiet --render-max-spp 8 "
    "--render-width 12 --render-height 9 --render-depth 3 --render-reference-spp 64";

TEST(Ch09Test, RenderStudyWritesErrorsSlopesAndImages) {
  const auto dir = fresh_dir("ch09_render"), cache = fresh_dir("ch09_render_cache");
  const ProgramRun run = run_program(k_program, k_render + " --reference-dir " + cache.string() +
                                                    " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CsvFile errors(dir / "render_error.csv");
  EXPECT_EQ(errors.header(),
            (std::vector<std::string>{"sampler", "depth", "spp", "rays", "rmse_vs_reference",
                                      "reference_standard_error", "rmse", "fitted"}));
  ASSERT_EQ(errors.size(), 3u * 2u * 4u);  // samplers x depths x spp
  for (std::size_t r = 0; r < errors.size(); ++r) {
    const double spp = errors.number(r, "spp"), depth = errors.number(r, "depth");
    // One camera ray per sample, at most depth more: equal spp is at most equal rays.
    EXPECT_GE(errors.number(r, "rays"), 12 * 9 * spp);
    EXPECT_LE(errors.number(r, "rays"), 12 * 9 * spp * (depth + 1));
    EXPECT_GT(errors.number(r, "rmse_vs_reference"), 0.0);
    EXPECT_LE(errors.number(r, "rmse"), errors.number(r, "rmse_vs_reference"));
  }
  EXPECT_EQ(CsvFile(dir / "render_slopes.csv").size(), 6u);
  EXPECT_TRUE(std::filesystem::exists(dir / "render_4spp.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "render_error_vs_spp.gp"));
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["render"]["slopes"].size(), 6u);
  EXPECT_EQ(summary["render"]["depths"], (std::vector<int>{1, 3}));

  const auto solo = fresh_dir("ch09_render_sobol");
  ASSERT_EQ(run_program(k_program, k_render + " --sampler sobol --threads 1 --reference-dir " +
                                       cache.string() + " --out " + solo.string())
                .exit_code,
            0);
  EXPECT_EQ(CsvFile(solo / "render_error.csv").size(), 2u * 4u);
  EXPECT_TRUE(std::filesystem::exists(solo / "render_4spp.png"));  // a sheet of one
}

TEST(Ch09Test, RenderStudyIsTheSameWhateverTheThreadCount) {
  const auto one = fresh_dir("ch09_render_threads1"), two = fresh_dir("ch09_render_threads2");
  const auto cache_one = fresh_dir("ch09_render_cache1"),
             cache_two = fresh_dir("ch09_render_cache2");
  const std::string flags = k_render + " --sampler sobol";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --reference-dir " + cache_one.string() +
                                       " --out " + one.string())
                .exit_code,
            0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --reference-dir " + cache_two.string() +
                                       " --out " + two.string())
                .exit_code,
            0);
  for (const char* name : {"render_error.csv", "render_slopes.csv", "summary.json"})
    EXPECT_EQ(read_text(one / name), read_text(two / name)) << name;
}

class Ch09BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch09BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch09BadInputTest,
    ::testing::Values(
        // Sobol' nets have 2^m points: N a power of two, 64 (three sizes) at least.
        BadInput{"--max-n 1000", "--max-n"}, BadInput{"--max-n 32", "--max-n"},
        BadInput{"--max-n 33554432", "--max-n"}, BadInput{"--max-n 0x100", "--max-n"},
        BadInput{"--budget 1000", "--budget"}, BadInput{"--budget 8", "--budget"},
        BadInput{"--budget -16", "--budget"}, BadInput{"--trials 1", "--trials"},
        BadInput{"--trials nan", "--trials"}, BadInput{"--dims 0", "--dims"},
        BadInput{"--dims 17", "--dims"}, BadInput{"--dims 1,,2", "--dims"},
        BadInput{"--picture-points 0", "--picture-points"}, BadInput{"--threads 0", "--threads"},
        BadInput{"--seed 18446744073709551616", "--seed"},
        BadInput{"--sampler halton", "--sampler"}, BadInput{"--sampler sobol,owen", "--sampler"},
        BadInput{"--render-max-spp 12", "--render-max-spp"},
        BadInput{"--render-scene furnace", "--render-scene"},
        BadInput{"--render-max-spp 16384 --render-width 4096 --render-height 4096",
                 "--render-max-spp"},
        // Far too much work in all: refused at once, with the estimate.
        BadInput{"--trials 100000 --max-n 16777216", "--trials"}),
    bad_input_name);

TEST(Ch09Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, k_tiny);
}

}  // namespace
