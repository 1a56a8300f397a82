// Assignment a3, the recursive estimator: the public tests (CTest label a3), graded on exact
// ray counts and on the furnace's mean and variance (a3_checks.hpp).

#include <gtest/gtest.h>

#include "assignments/a3/a3_checks.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A3, Task1RayCountsAreExact) {
  const TaskResult r = check_ray_counts(incident_radiance);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A3, Task1FurnaceMeanAndVarianceMatchTheClosedForms) {
  const TaskResult r = check_recursive_furnace(incident_radiance);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A3, Task1DepthZeroReturnsTheEmission) {
  const Scene furnace = make_furnace(0.7, 2.5);
  Rng rng(5, 5);
  RayCount count;
  const Color L = incident_radiance(furnace, {Vec3(0.0), {0.0, 0.6, 0.8}}, 0, {8, 0}, rng, count);
  EXPECT_DOUBLE_EQ(average(L), 2.5) << "at max_depth k = 0 the recursion returns the emission only";
  EXPECT_EQ(count.rays, 1u) << "at max_depth k = 0 one ray is traced: does the recursion stop at depth == k?";
}

TEST(A3, Task1EscapingRayBringsNoLight) {
  const Scene furnace = make_furnace(0.7, 2.5);
  Rng rng(5, 6);
  RayCount count;
  const Color L = incident_radiance(furnace, {Vec3(0.0, 0.0, 1e9), {0.0, 0.0, 1.0}}, 0, {2, 2}, rng, count);
  EXPECT_EQ(average(L), 0.0) << "a ray that leaves the scene brings no light";
}

}  // namespace
}  // namespace mcrt::testing::assignment
