// Assignment a5, variance reduction: the public tests (CTest label a5). Russian roulette and
// importance sampling are graded on the furnace's closed forms, next-event estimation on the
// furnace (where it is exact) and region by region against a4's path tracer (a5_checks.hpp).

#include <gtest/gtest.h>

#include "assignments/a5/a5_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A5, Task1RouletteFurnaceMatchesTheClosedForms) {
  const TaskResult r = check_roulette_furnace(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task1NoRouletteBeforeMinDepth) {
  // q = 0 after d = 4: every path stops at vertex 4, after its Le(x_4) is added.
  const Roulette roulette{4, RoulettePolicy::fixed, 0.0, 0.05};
  const PathSample p =
      subject().a5_single(roulette_estimator(roulette), 0.5, 1.0, {0.0, 0.0, 1.0}, 5, 5);
  const double L = p.radiance;
  EXPECT_EQ(p.rays, 5u)
      << "min_depth d = 4, q = 0: vertices 0..4 always go on to their Le, then the path stops";
  EXPECT_GT(L, 1.0) << "Le(x_0) = 1 and the later vertices' emission";
}

TEST(A5, Task2CosineFurnaceIsExact) {
  const TaskResult r = check_cosine_furnace_is_exact(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task2UniformFurnaceMeanAndVariance) {
  const TaskResult r = check_importance_furnace(subject(), cosine_power_pdf(0));
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task2CosineSquaredFurnaceMean) {
  const TaskResult r = check_importance_furnace(subject(), cosine_power_pdf(2));
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task3FurnaceIsExact) {
  const TaskResult r = check_nee_furnace_is_exact(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task3RegionsAgreeWithThePathTracer) {
  const TaskResult r = check_nee_regions(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task3TwoLightsAgreeWithThePathTracer) {
  const TaskResult r = check_nee_two_lights(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A5, Task3LightBeyondTheCapAgreesWithThePathTracer) {
  const TaskResult r = check_nee_light_beyond_cap(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
