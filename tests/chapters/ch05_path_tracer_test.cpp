// Chapter 05 as a student runs it: a tiny run and its outputs, reproducibility across thread
// counts, and bad input.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "io/image_file.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch05_path_tracer";

TEST(Ch05Test, TinyRunWritesImagesErrorTableAndSummary) {
  const auto dir = fresh_dir("ch05_smoke");
  const ProgramRun run = run_program(
      k_program, "--scene cornell-spheres --width 24 --height 18 --spp 1,4,16 --depth 4 "
                 "--threads 2 --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("fitted slope"), std::string::npos) << run.out;

  const CsvFile csv(dir / "rmse_vs_spp.csv");
  EXPECT_EQ(csv.header(),
            (std::vector<std::string>{"spp", "rmse", "seconds", "rays", "rays_per_second"}));
  ASSERT_EQ(csv.size(), 3u);
  const std::vector<double> rmse = csv.numbers("rmse");
  const int pixels = 24 * 18, spp[] = {1, 4, 16};
  for (std::size_t i = 0; i < csv.size(); ++i) {
    EXPECT_EQ(csv.number(i, "spp"), spp[i]);
    EXPECT_GT(rmse[i], 0.0);
    // Two renders of spp samples per pixel, each path 1 to depth + 1 = 5 closest-hit queries.
    const double rays = csv.number(i, "rays");
    EXPECT_GE(rays, 2.0 * pixels * spp[i]);
    EXPECT_LE(rays, 2.0 * pixels * spp[i] * 5);
    EXPECT_GT(csv.number(i, "rays_per_second"), 0.0);
  }
  // 16 times the samples: a quarter of the error, here within a factor 2 either way (432
  // pixels give the RMS error to about 10% at these spp; the factor is a coarse bound for a
  // smoke run, the law itself is tested in tests/checks/path_tracer_checks.cpp).
  EXPECT_GT(rmse[2], rmse[0] / 8.0);
  EXPECT_LT(rmse[2], rmse[0] / 2.0);

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["non_finite_samples"], 0);
  EXPECT_EQ(summary["scene"], "cornell-spheres");
  EXPECT_EQ(summary["depth"], 4);
  double rays = 0.0;
  for (double r : csv.numbers("rays")) rays += r;
  EXPECT_EQ(summary["rays"].get<double>(), rays);
  EXPECT_EQ(summary["rmse_vs_spp"].size(), 3u);
  EXPECT_GT(read_json(dir / "timings.json")["rays_per_second"].get<double>(), 0.0);
  const double slope = summary["rmse_slope"].get<double>();
  EXPECT_LT(slope, -0.2);  // coarse, as above: -1/2 within the noise of 432 pixels
  EXPECT_GT(slope, -0.8);
  EXPECT_EQ(summary["flags"]["spp"], "1,4,16");

  for (const char* name : {"spp_0001", "spp_0004", "spp_0016"}) {
    const mcrt::Image image = mcrt::read_pfm(dir / (std::string(name) + ".pfm"));
    EXPECT_EQ(image.width, 24);
    EXPECT_EQ(image.height, 18);
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(name) + ".png")));
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "noise_strip.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "rmse_vs_spp.gp"));
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary file left";
}

TEST(Ch05Test, SameSeedGivesByteIdenticalImagesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch05_threads1"), two = fresh_dir("ch05_threads2");
  const std::string flags = "--width 20 --height 16 --spp 2 --depth 6 --seed 5 --quiet";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  EXPECT_EQ(read_text(one / "spp_0002.pfm"), read_text(two / "spp_0002.pfm"));
  EXPECT_EQ(read_text(one / "spp_0002.png"), read_text(two / "spp_0002.png"));
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  EXPECT_EQ(read_text(one / "rmse_vs_spp.svg"), read_text(two / "rmse_vs_spp.svg"));
}

TEST(Ch05Test, HelpNamesEveryFlag) {
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"--scene", "--width", "--height", "--spp", "--depth", "--seed",
                           "--threads", "--out", "--quiet"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

class Ch05BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch05BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch05BadInputTest,
    ::testing::Values(BadInput{"--spp 0", "--spp"}, BadInput{"--spp 1,0,4", "--spp"},
                      BadInput{"--spp x", "--spp"}, BadInput{"--depth -1", "--depth"},
                      BadInput{"--scene moon", "--scene"},
                      BadInput{"--width 16384 --height 16384", "--width"},
                      BadInput{"--width 8192 --height 4096 --spp 4096", "--spp"},
                      BadInput{"--threads 0", "--threads"},
                      // Numbers are read as written: nothing clamped, no hex, finite reals only.
                      BadInput{"--depth 1e3", "--depth"}, BadInput{"--width 0x10", "--width"},
                      BadInput{"--emission nan", "--emission"},
                      BadInput{"--seed 18446744073709551616", "--seed"}),
    bad_input_name);

TEST(Ch05Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, "--width 8 --height 8 --spp 1");
}

}  // namespace
