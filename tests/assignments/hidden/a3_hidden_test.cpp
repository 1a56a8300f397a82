// Hidden tests of a3: ray counts at settings the public tests do not show.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a3/a3_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed and parameters of these tests: scripts/make-assignment --variant SECRET writes the
// variant's values into the autograder's copy of these lines (tests/assignments/answers/key.py,
// HIDDEN); these are the defaults.
inline constexpr std::uint64_t k_hidden_seed = 17;
inline constexpr int k_hidden_branches = 5;

/// 1 + N + ... + N^k (instructor tree only: it is a3.2's answer, without its saturation).
std::uint64_t geometric_ray_count(std::uint64_t n, int k) {
  std::uint64_t total = 0, level = 1;
  for (int j = 0; j <= k; ++j, level *= n) total += level;
  return total;
}

TEST(A3Hidden, RayCountsAtOtherBranches) {
  const int n = k_hidden_branches;
  for (int k : {0, 1, 2, 3}) {
    const std::uint64_t rays = subject()
                                   .recursive_single(0.3, 1.0, Vec3(0.0), {1.0, 0.0, 0.0}, n, k,
                                                     k_hidden_seed, static_cast<std::uint64_t>(k))
                                   .rays;
    EXPECT_EQ(rays, geometric_ray_count(n, k))
        << diagnose_ray_count(rays, n, k, geometric_ray_count(n, k));
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
