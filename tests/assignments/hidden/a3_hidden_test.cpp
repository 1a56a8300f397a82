// Hidden tests of a3: ray counts at settings the public tests do not show.

#include <gtest/gtest.h>

#include "assignments/a3/a3_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A3Hidden, RayCountsAtFiveBranches) {
  for (int k : {0, 1, 2, 3}) {
    const std::uint64_t rays =
        subject().recursive_single(0.3, 1.0, Vec3(0.0), {1.0, 0.0, 0.0}, 5, k, 17, static_cast<std::uint64_t>(k)).rays;
    EXPECT_EQ(rays, geometric_ray_count(5, k)) << diagnose_ray_count(rays, 5, k);
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
