// Hidden tests of a5 (their parameters travel as requests: the subject holds no hidden test): roulette from vertex 0 at another q; importance sampling at another
// albedo; NEE's depth cut traces at most 2k + 1 rays and a black room's NEE is the emission.

#include <gtest/gtest.h>

#include <cstdint>

#include "assignments/a5/a5_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

// The seed of these tests: scripts/make-assignment --variant SECRET writes the variant's value
// into the autograder's copy of this line (tests/assignments/answers/key.py, hidden_seed).
inline constexpr std::uint64_t k_hidden_seed = 4243;

TEST(A5Hidden, RouletteFromVertexZeroAtQPointNine) {
  const Roulette roulette{0, RoulettePolicy::fixed, 0.9, 0.05};
  RunningStats L;
  for (const FurnacePath& p : subject().a5_paths(roulette_estimator(roulette), 0.6, 20000, k_hidden_seed, 5))
    L.add(p.radiance);
  const double expected = furnace_radiance_untruncated(0.6, 1.0);
  const double p = z_test_p_value(L.mean(), expected, std::sqrt(furnace_roulette_variance(0.6, 1.0, 0, 0.9) / 20000.0));
  EXPECT_GE(p, 1e-6) << "mean " << L.mean() << ", expected " << expected << "\n" << diagnose_mean_ratio(L.mean(), expected);
}

TEST(A5Hidden, CosineFurnaceAtAlbedoPointEightIsExact) {
  const double L =
      subject().a5_single(importance_estimator(6, cosine_power_pdf(1)), 0.8, 1.0, {0.0, 1.0, 0.0}, k_hidden_seed + 1, 17).radiance;
  EXPECT_NEAR(L, furnace_radiance(0.8, 1.0, 6), 1e-9 * L) << "with the cosine pdf every furnace path is exact";
}

TEST(A5Hidden, NeeDepthCutTracesAtMostTwoKPlusOneRays) {
  const PathSample p = subject().a5_single(nee_estimator(nee_depth_cut(4)), 0.5, 1.0, {0.0, 0.0, 1.0}, k_hidden_seed + 2, 19);
  EXPECT_EQ(p.rays, 9u) << "k = 4: 5 closest-hit queries and one shadow ray at each of the 4 vertices before the cut";
}

}  // namespace
}  // namespace mcrt::testing::assignment
