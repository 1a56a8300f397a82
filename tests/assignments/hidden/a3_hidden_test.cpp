// Hidden tests of a3: ray counts at settings the public tests do not show.

#include <gtest/gtest.h>

#include "assignments/a3/a3_checks.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A3Hidden, RayCountsAtFiveBranches) {
  const Scene furnace = make_furnace(0.3, 1.0);
  for (int k : {0, 1, 2, 3}) {
    Rng rng(17, static_cast<std::uint64_t>(k));
    RayCount count;
    incident_radiance(furnace, {Vec3(0.0), {1.0, 0.0, 0.0}}, 0, {5, k}, rng, count);
    EXPECT_EQ(count.rays, geometric_ray_count(5, k)) << diagnose_ray_count(count.rays, 5, k);
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
