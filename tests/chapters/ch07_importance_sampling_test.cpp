// Chapter 07 as a student runs it: a tiny run and its outputs, the furnace example
// (every pixel of cosine.pfm exactly the closed form), reproducibility across thread counts,
// and bad input.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/run_folder.hpp"
#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "io/image_file.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch07_importance_sampling";

TEST(Ch07Test, TinyRunWritesImagesTablesAndSummary) {
  const auto dir = fresh_dir("ch07_smoke");
  const ProgramRun run =
      run_program(k_program,
                  "--width 24 --height 18 --spp 4 --depth 4 --reference-spp 8 --threads 2 "
                  "--out " +
                      dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("furnace variance with the cosine pdf"), std::string::npos) << run.out;

  const CsvFile variances(dir / "variance_vs_m.csv");
  ASSERT_EQ(variances.size(), 6u);  // uniform, cosine, cos^2, cos^4, cos^8, grazing
  const std::vector<std::string> pdfs{"uniform", "cosine", "cos^2", "cos^4", "cos^8", "grazing"};
  for (std::size_t i = 0; i < pdfs.size(); ++i) {
    EXPECT_EQ(variances.text(i, "pdf"), pdfs[i]);
    EXPECT_GT(variances.number(i, "scene_variance"), 0.0);
    EXPECT_GT(variances.number(i, "scene_mean"), 0.0);
  }
  EXPECT_EQ(variances.text(5, "m"), "");
  EXPECT_EQ(variances.number(0, "scene_variance_vs_uniform"), 1.0);
  // The cosine pdf in the furnace: 0 to rounding (squares of differences near 1e-16).
  EXPECT_LT(variances.number(1, "furnace_variance"), 1e-20);
  EXPECT_EQ(variances.number(1, "furnace_variance_theory"), 0.0);
  EXPECT_EQ(variances.text(3, "furnace_variance_theory"), "");  // m = 4: infinite

  // variance_curve.csv, the closed form over a continuous m: at m = 0 the uniform row's
  // closed form (both printed to 9 digits), 0 at m = 1 (the cosine pdf), and it grows
  // without bound towards the asymptote at m = 3 (b ~ 1/(3 - m), raised to the depth 4).
  const CsvFile curve(dir / "variance_curve.csv");
  ASSERT_GT(curve.size(), 100u);
  EXPECT_EQ(curve.number(0, "m"), 0.0);
  EXPECT_EQ(curve.number(0, "furnace_variance_theory"),
            variances.number(0, "furnace_variance_theory"));
  double at_one = 1.0, last_m = 0.0;
  for (std::size_t i = 0; i < curve.size(); ++i) {
    EXPECT_GT(curve.number(i, "m"), i == 0 ? -1.0 : last_m);  // increasing
    last_m = curve.number(i, "m");
    if (std::abs(last_m - 1.0) < 1e-12) at_one = curve.number(i, "furnace_variance_theory");
  }
  EXPECT_LT(at_one, 1e-12);
  EXPECT_LT(last_m, 3.0);
  EXPECT_GT(curve.number(curve.size() - 1, "furnace_variance_theory"),
            1e3 * variances.number(0, "furnace_variance_theory"));

  const CsvFile equal_time(dir / "equal_time.csv");
  ASSERT_EQ(equal_time.size(), 4u);
  EXPECT_EQ(equal_time.text(0, "image"), "uniform");
  EXPECT_EQ(equal_time.text(2, "image"), "cosine_equal_time");
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GT(equal_time.number(i, "relative_mse"), 0.0);
  // Equal rays: the equal-time image's rays are within one sample per pixel of the uniform's.
  const double rays_per_spp = equal_time.number(1, "rays") / 4.0;
  EXPECT_NEAR(equal_time.number(2, "rays"), equal_time.number(0, "rays"), rays_per_spp);

  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["scene"], "cornell");
  EXPECT_EQ(summary["non_finite_samples"], 0);
  EXPECT_EQ(summary["variance_vs_m"].size(), 6u);
  EXPECT_EQ(summary["equal_time"].size(), 4u);
  EXPECT_LT(summary["furnace"]["cosine_variance"].get<double>(), 1e-20);
  EXPECT_EQ(summary["flags"]["powers"], "0,1,2,4,8");
  for (const char* stem : {"uniform", "cosine", "cosine_equal_time", "reference"}) {
    const mcrt::Image image = mcrt::read_pfm(dir / (std::string(stem) + ".pfm"));
    EXPECT_EQ(image.width, 24);
    EXPECT_EQ(image.height, 18);
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(stem) + ".png")));
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "noise_strip.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "variance_vs_m.gp"));
  for (const auto& entry : std::filesystem::directory_iterator(dir))  // the manifest aside
    if (entry.path().filename() != mcrt::k_manifest_name) {
      EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary file left";
    }
}

// The example: with the cosine pdf every path in the furnace returns Le (1 - a^6) /
// (1 - a), so every pixel is that number, rounded once to the PFM's 32-bit float.
TEST(Ch07Test, CosineFurnaceImageIsExactlyTheClosedForm) {
  const auto dir = fresh_dir("ch07_furnace");
  const ProgramRun run =
      run_program(k_program,
                  "--scene furnace --albedo 0.6 --emission 1 --depth 5 --width 16 --height 16 "
                  "--spp 4 --quiet --out " +
                      dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const float expected = static_cast<float>((1.0 - std::pow(0.6, 6)) / (1.0 - 0.6));
  const mcrt::Image image = mcrt::read_pfm(dir / "cosine.pfm");
  ASSERT_EQ(image.pixels.size(), 256u);
  for (const auto& pixel : image.pixels)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(static_cast<float>(pixel[c]), expected);
  // The uniform image is noisy around the same value.
  const mcrt::Image uniform = mcrt::read_pfm(dir / "uniform.pfm");
  EXPECT_NE(uniform.pixels[0], image.pixels[0]);
}

TEST(Ch07Test, SameSeedGivesByteIdenticalOutputsWhateverTheThreadCount) {
  const auto one = fresh_dir("ch07_threads1"), two = fresh_dir("ch07_threads2");
  const std::string flags =
      "--width 16 --height 12 --spp 2 --depth 4 --reference-spp 4 --seed 5 --quiet";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  // summary.json holds no timing, thread count or --out: the same file whatever --threads.
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  for (const char* file : {"uniform.pfm", "cosine.pfm", "cosine_equal_time.pfm", "reference.pfm",
                           "uniform.png", "noise_strip.png", "variance_curve.csv",
                           "variance_vs_m.gp", "variance_vs_m.png", "variance_vs_m.svg"})
    EXPECT_EQ(read_text(one / file), read_text(two / file)) << file;
  EXPECT_EQ(CsvFile(one / "variance_vs_m.csv").without({"scene_seconds"}),
            CsvFile(two / "variance_vs_m.csv").without({"scene_seconds"}));
  EXPECT_EQ(CsvFile(one / "equal_time.csv").without({"seconds"}),
            CsvFile(two / "equal_time.csv").without({"seconds"}));
}

TEST(Ch07Test, HelpNamesEveryFlag) {
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag : {"--scene", "--albedo", "--width", "--spp", "--depth", "--powers",
                           "--reference-spp", "--seed", "--threads", "--out", "--quiet"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

class Ch07BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch07BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch07BadInputTest,
    ::testing::Values(BadInput{"--spp 0", "--spp"}, BadInput{"--depth -1", "--depth"},
                      BadInput{"--powers 1,x", "--powers"}, BadInput{"--powers 65", "--powers"},
                      BadInput{"--reference-spp 0", "--reference-spp"},
                      BadInput{"--scene moon", "--scene"},
                      BadInput{"--width 8192 --height 4096 --spp 4096", "--spp"},
                      BadInput{"--threads 0", "--threads"},
                      // Numbers are read as written: nothing clamped, no hex, finite reals only.
                      BadInput{"--reference-spp 0x10", "--reference-spp"},
                      BadInput{"--depth nan", "--depth"}, BadInput{"--albedo inf", "--albedo"},
                      BadInput{"--seed 18446744073709551616", "--seed"}),
    bad_input_name);

TEST(Ch07Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, "--width 8 --height 8 --spp 1 --reference-spp 1");
}

}  // namespace
