// Hidden tests of a3: ray counts at settings the public tests do not show.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a3/a3_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed of these tests: scripts/make-assignment --variant SECRET writes the variant's value
// into the autograder's copy of this line (tests/assignments/answers/key.py, hidden_seed).
inline constexpr std::uint64_t k_hidden_seed = 17;

TEST(A3Hidden, RayCountsAtFiveBranches) {
  for (int k : {0, 1, 2, 3}) {
    const std::uint64_t rays =
        subject().recursive_single(0.3, 1.0, Vec3(0.0), {1.0, 0.0, 0.0}, 5, k, k_hidden_seed, static_cast<std::uint64_t>(k)).rays;
    EXPECT_EQ(rays, geometric_ray_count(5, k)) << diagnose_ray_count(rays, 5, k);
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
