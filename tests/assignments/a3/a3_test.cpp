// Assignment a3, the recursive estimator: the public tests (CTest label a3), graded on exact
// ray counts and on the furnace's mean and variance (a3.1), and on the ray-count prediction
// max_rays_per_sample (a3.2), exactly (a3_checks.hpp).

#include <gtest/gtest.h>

#include "assignments/a3/a3_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A3, Task1RayCountsAreExact) {
  const TaskResult r = check_ray_counts(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A3, Task1FurnaceMeanAndVarianceMatchTheClosedForms) {
  const TaskResult r = check_recursive_furnace(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A3, Task1DepthZeroReturnsTheEmission) {
  const PathSample p = subject().recursive_single(0.7, 2.5, Vec3(0.0), {0.0, 0.6, 0.8}, 8, 0, 5, 5);
  EXPECT_DOUBLE_EQ(p.radiance, 2.5) << "at max_depth k = 0 the recursion returns the emission only";
  EXPECT_EQ(p.rays, 1u)
      << "at max_depth k = 0 one ray is traced: does the recursion stop at depth == k?";
}

TEST(A3, Task1EscapingRayBringsNoLight) {
  const PathSample p =
      subject().recursive_single(0.7, 2.5, {0.0, 0.0, 1e9}, {0.0, 0.0, 1.0}, 2, 2, 5, 6);
  EXPECT_EQ(p.radiance, 0.0) << "a ray that leaves the scene brings no light";
}

TEST(A3, Task2PredictionMatchesTheClosedForm) {
  const TaskResult r = check_predicted_rays(subject(), k_a3_prediction_cases);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A3, Task2PredictionCountsYourRecursion) {
  const TaskResult r = check_prediction_counts_your_recursion(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A3, Task2PredictionSaturatesInsteadOfOverflowing) {
  const TaskResult r = check_prediction_saturates(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
