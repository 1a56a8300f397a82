// Chapter 08's light choice (chapters/08_next_event_estimation/light_choice.hpp) as a student
// runs it: light_choice.png and light_choice.csv written, equal rays for both choices, the
// choice's probabilities, and the lesson of the page: power choice wins away from the dim light
// and loses beside it. (The estimator's statistics: tests/render/light_choice_test.cpp.)

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "chapters/csv_file.hpp"
#include "chapters/run_program.hpp"

using namespace mcrt::testing;

namespace {

TEST(Ch08LightChoiceTest, RunWritesTheFigureAndTheTableAtEqualRays) {
  const auto dir = fresh_dir("ch08_light_choice");
  const auto refs = dir.parent_path() / "ch08_light_choice_cache";
  const ProgramRun run = run_program(
      "ch08_next_event_estimation",
      "--width 16 --height 12 --spp 1 --reference-spp 2 --ray-budgets 2 --plates-spp 1 --quiet "
      "--reference-dir " +
          refs.string() + " --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "light_choice.png"));
  const CsvFile csv(dir / "light_choice.csv");
  ASSERT_EQ(csv.size(), 6u);  // 2 choices x 3 regions
  double uniform_rest = 0.0, power_rest = 0.0, uniform_near = 0.0, power_near = 0.0;
  for (std::size_t i = 0; i < csv.size(); ++i) {
    EXPECT_EQ(csv.number(i, "rays_per_pixel"), 16.0) << i;  // one shadow ray a sample, 16 spp
    const bool uniform = csv.text(i, "choice") == "uniform";
    // The CSV keeps 6 significant digits.
    EXPECT_NEAR(csv.number(i, "p_dim"), uniform ? 0.5 : 4.0 / 404.0, 1e-8);
    const std::string region = csv.text(i, "region");
    if (region == "rest") (uniform ? uniform_rest : power_rest) = csv.number(i, "rel_mse");
    if (region == "beside_dim") (uniform ? uniform_near : power_near) = csv.number(i, "rel_mse");
  }
  // Measured at seed 1: 31x and 1/14x; the variance ratios behind them are ~100 and ~500
  // (tests/render/light_choice_test.cpp), so a factor 3 holds for any seed.
  EXPECT_GT(uniform_rest, 3.0 * power_rest);
  EXPECT_GT(power_near, 3.0 * uniform_near);
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["light_choice"].size(), 6u);
}

}  // namespace
