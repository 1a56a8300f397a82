// Hidden tests of a4: a black furnace gives exactly the emission; a brighter albedo's mean.
// Their parameters travel as requests to the subject, which holds no hidden test.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a4/a4_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed of these tests: scripts/make-assignment --variant SECRET writes the variant's value
// into the autograder's copy of this line (tests/assignments/answers/key.py, hidden_seed).
inline constexpr std::uint64_t k_hidden_seed = 4242;

TEST(A4Hidden, BlackFurnaceGivesTheEmissionExactly) {
  EXPECT_DOUBLE_EQ(subject().path_single(0.0, 1.25, {0.0, 0.0, -1.0}, 6, k_hidden_seed + 1, 9).radiance, 1.25)
      << "a black furnace reflects nothing: the path is its emission";
}

TEST(A4Hidden, FurnaceMeanAtAlbedoPointEight) {
  const std::vector<double> values = subject().path_furnace(0.8, 5, 20000, k_hidden_seed, 3);
  RunningStats s;
  for (double x : values) s.add(x);
  const double expected = furnace_radiance(0.8, 1.0, 5);
  const double p = z_test_p_value(s.mean(), expected, std::sqrt(furnace_radiance_variance(0.8, 1.0, 5) / 20000.0));
  EXPECT_GE(p, 1e-6) << "mean " << s.mean() << ", expected " << expected << "\n" << diagnose_mean_ratio(s.mean(), expected);
}

}  // namespace
}  // namespace mcrt::testing::assignment
