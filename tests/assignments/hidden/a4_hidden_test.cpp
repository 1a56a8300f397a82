// Hidden tests of a4: a black furnace gives exactly the emission; another albedo's mean.
// Their parameters travel as requests to the subject, which holds no hidden test.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a4/a4_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed and parameters of these tests: scripts/make-assignment --variant SECRET writes the
// variant's values into the autograder's copy of these lines (tests/assignments/answers/key.py,
// HIDDEN); these are the defaults.
inline constexpr std::uint64_t k_hidden_seed = 4242;
inline constexpr double k_hidden_emission = 1.25;  // of the black furnace
inline constexpr double k_hidden_albedo = 0.8;     // of the furnace at depth 5

TEST(A4Hidden, BlackFurnaceGivesTheEmissionExactly) {
  EXPECT_DOUBLE_EQ(subject()
                       .path_single(0.0, k_hidden_emission, {0.0, 0.0, -1.0}, 6, k_hidden_seed + 1,
                                    9)
                       .radiance,
                   k_hidden_emission)
      << "a black furnace reflects nothing: the path is its emission";
}

TEST(A4Hidden, FurnaceMeanAtAnotherAlbedo) {
  const double a = k_hidden_albedo;
  const std::vector<double> values = subject().path_furnace(a, 5, 20000, k_hidden_seed, 3);
  RunningStats s;
  for (double x : values) s.add(x);
  const double expected = furnace_radiance(a, 1.0, 5);
  const double p =
      z_test_p_value(s.mean(), expected, std::sqrt(furnace_radiance_variance(a, 1.0, 5) / 20000.0));
  EXPECT_GE(p, 1e-6) << "mean " << s.mean() << ", expected " << expected << "\n"
                     << diagnose_mean_ratio(s.mean(), expected);
}

}  // namespace
}  // namespace mcrt::testing::assignment
