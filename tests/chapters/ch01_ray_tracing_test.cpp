// Chapter 01 as a student runs it: tiny renders, their outputs, reproducibility across thread
// counts, and every kind of bad input.

#include <cmath>

#include <gtest/gtest.h>

#include "chapters/run_program.hpp"
#include "io/image_file.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch01_ray_tracing";

TEST(Ch01Test, RendersTheCornellBoxAndWritesItsOutputs) {
  const auto dir = fresh_dir("ch01_smoke");
  const ProgramRun run =
      run_program(k_program, "--width 32 --height 24 --spp 2 --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.out.empty());  // --quiet
  const mcrt::Image image = mcrt::read_pfm(dir / "image.pfm");
  EXPECT_EQ(image.width, 32);
  EXPECT_EQ(image.height, 24);
  EXPECT_GT(mcrt::mean_radiance(image), 0.0);
  EXPECT_TRUE(std::filesystem::exists(dir / "image.png"));
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["scene"], "cornell");
  EXPECT_EQ(summary["spp"], 2);
  // Every pixel sample traces one camera ray and at most one shadow ray.
  const int samples = 32 * 24 * 2;
  EXPECT_GE(summary["rays"].get<int>(), samples);
  EXPECT_LE(summary["rays"].get<int>(), 2 * samples);
  EXPECT_EQ(summary["non_finite_samples"], 0);
  EXPECT_EQ(summary["flags"]["width"], "32");
  EXPECT_GT(read_json(dir / "timings.json")["rays_per_second"].get<double>(), 0.0);
  // image.png, image.pfm, summary.json, timings.json: no temporaries left
  EXPECT_EQ(file_count(dir), 5);  // the four files and the run's manifest
}

// The floor below the cornell lamp, shaded by the chapter itself: the inverse-square law
// against the scene's numbers written out here (white rho 0.73, Le 15 over a 130 x 105 lamp
// whose point light hangs 1e-3 below the ceiling's lamp at y = 554, so h = 553.999), and the
// cos^4 law at the floor points the lamp sees. 1e-6: the shadow ray starts a spawn offset off
// the floor, about 1e-7 of h; a missing cosine or a distance not squared is off by over 1e-2.
TEST(Ch01Test, ShadingFollowsTheInverseSquareAndCosFourthLaws) {
  const auto dir = fresh_dir("ch01_falloff");
  ASSERT_EQ(run_program(k_program, "--width 8 --height 6 --quiet --out " + dir.string()).exit_code,
            0);
  const auto falloff = read_json(dir / "summary.json")["falloff"];
  const double h = 553.999, closed_form = 0.73 / M_PI * 15.0 * 130.0 * 105.0 / (h * h);
  EXPECT_NEAR(falloff["height"].get<double>(), h, 1e-9 * h);
  EXPECT_NEAR(falloff["predicted_below_lamp"].get<double>(), closed_form, 1e-12 * closed_form);
  EXPECT_NEAR(falloff["measured_below_lamp"].get<double>(), closed_form, 1e-6 * closed_form);
  // The floor is 555 wide and the lamp above its middle: points up to 25 degrees, in 2.5 degree
  // steps, in four directions, less those behind the two boxes.
  EXPECT_GE(falloff["points"].get<int>(), 15);
  EXPECT_EQ(falloff["largest_angle_degrees"].get<double>(), 25.0);
  EXPECT_LT(falloff["largest_relative_deviation"].get<double>(), 1e-6);
}

TEST(Ch01Test, PrintsASummaryAndHelp) {
  const auto dir = fresh_dir("ch01_table");
  const ProgramRun run = run_program(k_program, "--width 8 --height 8 --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("rays per second"), std::string::npos);
  const ProgramRun help = run_program(k_program, "--help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* flag :
       {"--width", "--height", "--spp", "--scene", "--seed", "--threads", "--out", "--quiet"})
    EXPECT_NE(help.out.find(flag), std::string::npos) << flag;
}

TEST(Ch01Test, SameSeedGivesByteIdenticalImagesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch01_threads1"), two = fresh_dir("ch01_threads2");
  const std::string flags =
      "--scene cornell-spheres --width 40 --height 30 --spp 3 --seed 9 --quiet";
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  // summary.json holds no timing, thread count or --out: the same file whatever --threads.
  EXPECT_EQ(read_text(one / "summary.json"), read_text(two / "summary.json"));
  EXPECT_EQ(read_text(one / "image.pfm"), read_text(two / "image.pfm"));
  EXPECT_EQ(read_text(one / "image.png"), read_text(two / "image.png"));
  const auto other = fresh_dir("ch01_seed10");
  ASSERT_EQ(run_program(k_program,
                        "--scene cornell-spheres --width 40 --height 30 --spp 3 "
                        "--seed 10 --quiet --out " +
                            other.string())
                .exit_code,
            0);
  EXPECT_NE(read_text(one / "image.pfm"), read_text(other / "image.pfm"));  // jitter differs
}

TEST(Ch01Test, EveryScene) {
  for (const std::string scene : {"cornell", "cornell-spheres", "furnace"}) {
    const auto dir = fresh_dir("ch01_scene_" + scene);
    const ProgramRun run =
        run_program(k_program,
                    "--scene " + scene + " --width 16 --height 12 --quiet --out " + dir.string());
    EXPECT_EQ(run.exit_code, 0) << scene << ": " << run.err;
  }
}

TEST(Ch01Test, FurnaceSeesOnlyItsEmission) {
  // Direct light only, no point light: every camera ray returns the walls' Le exactly.
  const auto dir = fresh_dir("ch01_furnace");
  ASSERT_EQ(run_program(k_program,
                        "--scene furnace --emission 2.5 --albedo 0.3 --width 8 "
                        "--height 8 --quiet --out " +
                            dir.string())
                .exit_code,
            0);
  const mcrt::Image image = mcrt::read_pfm(dir / "image.pfm");
  for (const mcrt::Color& c : image.pixels) EXPECT_EQ(c, mcrt::Color(2.5));
}

class Ch01BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch01BadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch01BadInputTest,
    ::testing::Values(BadInput{"--width 0", "--width"}, BadInput{"--width -3", "--width"},
                      BadInput{"--width abc", "--width"}, BadInput{"--spp 0", "--spp"},
                      BadInput{"--height 1.5", "--height"},
                      BadInput{"--frobnicate", "--frobnicate"}, BadInput{"--scene moon", "--scene"},
                      BadInput{"--width 10000 --height 10000", "--width"},
                      BadInput{"--threads 0", "--threads"}, BadInput{"--seed -1", "--seed"},
                      BadInput{"--albedo 1.5", "--albedo"},
                      // Numbers are read as written: nothing clamped, no hex, finite reals only.
                      BadInput{"--seed 18446744073709551616", "--seed"},
                      BadInput{"--seed 0x10", "--seed"}, BadInput{"--width 0x10", "--width"},
                      BadInput{"--spp 1e3", "--spp"}, BadInput{"--albedo nan", "--albedo"},
                      BadInput{"--emission inf", "--emission"},
                      BadInput{"--emission nan", "--emission"},
                      // 8192 x 4096 x 65536 spp x 2 rays: refused at once, with the estimate.
                      BadInput{"--width 8192 --height 4096 --spp 65536", "--spp"}),
    bad_input_name);

TEST(Ch01Test, UnwritableOutputExitsWithCodeOneAndLeavesNothing) {
  expect_unwritable_output_fails(k_program, "--width 8 --height 8");
}

TEST(Ch01Test, StdoutThatCannotBeWrittenExitsWithCodeOne) {
  expect_full_stdout_fails(k_program, "--width 8 --height 8");
}

}  // namespace
