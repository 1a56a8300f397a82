// Chapter 08's study of Veach's plates (chapters/08_next_event_estimation/plates.hpp) as a
// student runs it: plates.png and plates.csv written, equal rays for every strategy, the
// summary's "plates" table, byte-identical outputs at 1 and 2 threads, and --plates-spp refused
// where it is out of range. (The study's statistics: tests/render/glossy_direct_test.cpp.)

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"
#include "io/image_file.hpp"

using namespace mcrt::testing;

namespace {

const std::string k_program = "ch08_next_event_estimation";
// The smallest shoot-out that runs; the plates at 32 x 24 so that each of the 16 regions holds
// pixels (at 12 x 9 a plate is one row and a highlight less than a pixel from the next).
const std::string k_tiny =
    "--width 32 --height 24 --spp 1 --reference-spp 2 --ray-budgets 2 --plates-spp 2 ";

TEST(Ch08PlatesTest, RunWritesTheFigureAndTheTableAtEqualRays) {
  const auto dir = fresh_dir("ch08_plates");
  const auto refs = dir.parent_path() / "ch08_plates_cache";
  const ProgramRun run = run_program(k_program, k_tiny + "--quiet --threads 2 --reference-dir " +
                                                    refs.string() + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "plates.png"));
  const CsvFile csv(dir / "plates.csv");
  ASSERT_EQ(csv.size(), 4u * 4u * 4u);  // plates x lights x strategies
  const std::set<std::string> strategies{"light", "bsdf", "mis_balance", "mis_power"};
  for (std::size_t i = 0; i < csv.size(); ++i) {
    EXPECT_TRUE(strategies.count(csv.text(i, "strategy"))) << i;
    EXPECT_TRUE(strategies.count(csv.text(i, "winner"))) << i;
    // Equal rays: every strategy traces the camera ray and two more per plate sample, and all
    // see the same camera rays, so the counts agree exactly.
    EXPECT_EQ(csv.number(i, "rays_per_pixel"), csv.number(0, "rays_per_pixel"));
    EXPECT_LE(csv.number(i, "rays_per_pixel"), 3.0 * 2.0);  // 3 rays x 2 spp at most
    EXPECT_GT(csv.number(i, "x1"), csv.number(i, "x0")) << i;
    EXPECT_GT(csv.number(i, "y1"), csv.number(i, "y0")) << i;
    EXPECT_GE(csv.number(i, "rel_mse_vs_best"), 1.0);
    // The winner of a cell is the strategy whose ratio to the best is 1.
    if (csv.text(i, "strategy") == csv.text(i, "winner")) {
      EXPECT_EQ(csv.number(i, "rel_mse_vs_best"), 1.0);
    }
  }
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["plates"].size(), 64u);
  EXPECT_EQ(summary["flags"]["plates-spp"], "2") << summary["flags"].dump();
}

TEST(Ch08PlatesTest, SameSeedGivesByteIdenticalPlatesWhateverTheThreadCount) {
  const auto one = fresh_dir("ch08_plates_threads1"), two = fresh_dir("ch08_plates_threads2");
  const auto refs = one.parent_path() / "ch08_plates_threads_cache";
  const std::string flags = k_tiny + "--seed 7 --quiet --reference-dir " + refs.string();
  ASSERT_EQ(run_program(k_program, flags + " --threads 1 --out " + one.string()).exit_code, 0);
  ASSERT_EQ(run_program(k_program, flags + " --threads 2 --out " + two.string()).exit_code, 0);
  for (const char* file : {"plates.png", "plates.csv", "summary.json"})
    EXPECT_EQ(read_text(one / file), read_text(two / file)) << file;
  // And another seed gives other noise (the files are not constant).
  const auto other = fresh_dir("ch08_plates_seed8");
  ASSERT_EQ(run_program(k_program, k_tiny + "--seed 8 --quiet --reference-dir " + refs.string() +
                                       " --out " + other.string())
                .exit_code,
            0);
  EXPECT_NE(read_text(one / "plates.csv"), read_text(other / "plates.csv"));
}

class Ch08PlatesBadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(Ch08PlatesBadInputTest, ExitsWithCodeTwoAndOneLineNamingTheFlag) {
  expect_refused(k_program, GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Flags, Ch08PlatesBadInputTest,
    ::testing::Values(BadInput{"--plates-spp 0", "--plates-spp"},
                      BadInput{"--plates-spp 5000", "--plates-spp"},
                      BadInput{"--plates-spp 1.5", "--plates-spp"},
                      BadInput{"--plates-spp=", "--plates-spp"},
                      // over the ray limit: the message lists the flags that set the work
                      BadInput{"--width 4096 --height 4096 --plates-spp 4096", "--plates-spp"}),
    bad_input_name);

}  // namespace
