// Hidden tests of a4: a black furnace gives exactly the emission; a brighter albedo's mean.

#include <gtest/gtest.h>

#include "assignments/a4/a4_checks.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A4Hidden, BlackFurnaceGivesTheEmissionExactly) {
  const Scene furnace = make_furnace(0.0, 1.25);
  Rng rng(9, 9);
  RayCount count;
  EXPECT_DOUBLE_EQ(average(estimate_path_radiance(furnace, {Vec3(0.0), {0.0, 0.0, -1.0}}, 6, rng, count)), 1.25)
      << "a black furnace reflects nothing: the path is its emission";
}

TEST(A4Hidden, FurnaceMeanAtAlbedoPointEight) {
  const std::vector<double> values = furnace_values(estimate_path_radiance, 0.8, 5, 20000, 4242, 3);
  RunningStats s;
  for (double x : values) s.add(x);
  const double expected = furnace_radiance(0.8, 1.0, 5);
  const double p = z_test_p_value(s.mean(), expected, std::sqrt(furnace_radiance_variance(0.8, 1.0, 5) / 20000.0));
  EXPECT_GE(p, 1e-6) << "mean " << s.mean() << ", expected " << expected << "\n" << diagnose_mean_ratio(s.mean(), expected);
}

}  // namespace
}  // namespace mcrt::testing::assignment
