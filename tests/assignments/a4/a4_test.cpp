// Assignment a4, the path tracer: the public tests (CTest label a4), graded on the furnace's
// closed forms and on region-by-region agreement with a reference render (a4_checks.hpp).

#include <gtest/gtest.h>

#include "assignments/a4/a4_checks.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A4, Task1FurnaceMeanAndVarianceMatchTheClosedForms) {
  const TaskResult r = check_path_furnace(estimate_path_radiance);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A4, Task1RegionsAgreeWithTheReference) {
  const TaskResult r = check_reference_regions(estimate_path_radiance);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A4, Task1TracesAtMostKPlusOneRays) {
  const Scene furnace = make_furnace(0.5, 1.0);
  Rng rng(3, 3);
  RayCount count;
  estimate_path_radiance(furnace, {Vec3(0.0), {0.0, 0.0, 1.0}}, 5, rng, count);
  EXPECT_EQ(count.rays, 6u) << "k = 5 bounces: k + 1 closest-hit queries in the furnace";
}

TEST(A4, Task1DepthZeroIsTheEmission) {
  const Scene furnace = make_furnace(0.5, 1.5);
  Rng rng(3, 4);
  RayCount count;
  EXPECT_DOUBLE_EQ(average(estimate_path_radiance(furnace, {Vec3(0.0), {0.0, 1.0, 0.0}}, 0, rng, count)), 1.5)
      << "with max_depth 0 the path is the first hit's emission";
}

}  // namespace
}  // namespace mcrt::testing::assignment
