// Hidden tests of a7 (their parameters travel as requests: the subject holds no hidden test):
// jittered points on another grid, in four dimensions (two padded pairs), at keys the public
// tests never use; scrambled Halton in dimensions 2 and 3 (bases 5 and 7); the radical inverse
// in bases 11 and 13.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a7/a7_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed and grid of these tests: scripts/make-assignment --variant SECRET writes the
// variant's values into the autograder's copy of these lines (tests/assignments/answers/key.py,
// HIDDEN); these are the defaults.
inline constexpr std::uint64_t k_hidden_seed = 7331;
inline constexpr std::uint32_t k_hidden_grid = 11;

TEST(A7Hidden, JitteredStrataOfTwoPairsOnAnotherGrid) {
  const std::uint32_t k = k_hidden_grid, n = k * k;
  const std::vector<double> v = subject().a7_points(A7PointSet::jittered, n, 4,
                                                    a7_first_key(k_hidden_seed), 1, a7_indices(n));
  EXPECT_EQ(strata_problem(v, n, 4, 0, k, 1, k), "");
  EXPECT_EQ(strata_problem(v, n, 4, 2, k, 3, k), "");
}

TEST(A7Hidden, HaltonAndRadicalInverseInFurtherBases) {
  // n = 35 = 5 x 7: dimensions 2 and 3 (bases 5 and 7) put one point in each of 5 x 7 boxes
  const std::vector<double> v =
      subject().a7_points(A7PointSet::halton, 35, 4, a7_first_key(k_hidden_seed) + 1, 1,
                          a7_indices(35));
  EXPECT_EQ(strata_problem(v, 35, 4, 2, 5, 3, 7), "");
  const TaskResult r = check_radical_inverse(subject(), {11, 13});
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
