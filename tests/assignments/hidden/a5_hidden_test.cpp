// Hidden tests of a5 (their parameters travel as requests: the subject holds no hidden test): roulette from vertex 0 at another q; importance sampling at another
// albedo; NEE's depth cut traces at most 2k + 1 rays and a black room's NEE is the emission.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a5/a5_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed and parameters of these tests: scripts/make-assignment --variant SECRET writes the
// variant's values into the autograder's copy of these lines (tests/assignments/answers/key.py,
// HIDDEN); these are the defaults.
inline constexpr std::uint64_t k_hidden_seed = 4243;
inline constexpr double k_hidden_roulette_q = 0.9;  // above 4 a^2 / 3: a finite variance
inline constexpr double k_hidden_roulette_albedo = 0.6;
inline constexpr double k_hidden_cosine_albedo = 0.8;

TEST(A5Hidden, RouletteFromVertexZero) {
  const double q = k_hidden_roulette_q, a = k_hidden_roulette_albedo;
  const Roulette roulette{0, RoulettePolicy::fixed, q, 0.05};
  RunningStats L;
  for (const FurnacePath& p :
       subject().a5_paths(roulette_estimator(roulette), a, 20000, k_hidden_seed, 5))
    L.add(p.radiance);
  const double expected = furnace_radiance_untruncated(a, 1.0);
  const double p = z_test_p_value(L.mean(), expected,
                                  std::sqrt(furnace_roulette_variance(a, 1.0, 0, q) / 20000.0));
  EXPECT_GE(p, 1e-6) << "mean " << L.mean() << ", expected " << expected << "\n"
                     << diagnose_mean_ratio(L.mean(), expected);
}

TEST(A5Hidden, CosineFurnaceAtAnotherAlbedoIsExact) {
  const double a = k_hidden_cosine_albedo;
  const double L = subject()
                       .a5_single(importance_estimator(6, cosine_power_pdf(1)), a, 1.0,
                                  {0.0, 1.0, 0.0}, k_hidden_seed + 1, 17)
                       .radiance;
  EXPECT_NEAR(L, furnace_radiance(a, 1.0, 6), 1e-9 * L)
      << "with the cosine pdf every furnace path is exact";
}

TEST(A5Hidden, NeeDepthCutTracesAtMostTwoKPlusOneRays) {
  const PathSample p = subject().a5_single(nee_estimator(nee_depth_cut(4)), 0.5, 1.0,
                                           {0.0, 0.0, 1.0}, k_hidden_seed + 2, 19);
  EXPECT_EQ(p.rays, 9u)
      << "k = 4: 5 closest-hit queries and one shadow ray at each of the 4 vertices before the cut";
}

}  // namespace
}  // namespace mcrt::testing::assignment
