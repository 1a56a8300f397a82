// Hidden tests of a5: roulette from vertex 0 at another q; importance sampling at another
// albedo; NEE's depth cut traces at most 2k + 1 rays and a black room's NEE is the emission.

#include <gtest/gtest.h>

#include "assignments/a5/a5_checks.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A5Hidden, RouletteFromVertexZeroAtQPointNine) {
  const Scene furnace = make_furnace(0.6, 1.0);
  const Roulette roulette{0, RoulettePolicy::fixed, 0.9, 0.05};
  RunningStats L;
  for (const FurnacePath& p : a5_furnace_paths(furnace, 20000, 4243, 5, [&](const Scene& s, const Ray& r, Rng& rng, RayCount& c) {
         return estimate_path_radiance_roulette(s, r, roulette, rng, c);
       }))
    L.add(p.radiance);
  const double expected = furnace_radiance_untruncated(0.6, 1.0);
  const double p = z_test_p_value(L.mean(), expected, std::sqrt(furnace_roulette_variance(0.6, 1.0, 0, 0.9) / 20000.0));
  EXPECT_GE(p, 1e-6) << "mean " << L.mean() << ", expected " << expected << "\n" << diagnose_mean_ratio(L.mean(), expected);
}

TEST(A5Hidden, CosineFurnaceAtAlbedoPointEightIsExact) {
  const Scene furnace = make_furnace(0.8, 1.0);
  Rng rng(17, 17);
  RayCount count;
  const double L = average(estimate_importance_path_radiance(furnace, {Vec3(0.0), {0.0, 1.0, 0.0}}, 6, cosine_power_pdf(1), rng, count));
  EXPECT_NEAR(L, furnace_radiance(0.8, 1.0, 6), 1e-9 * L) << "with the cosine pdf every furnace path is exact";
}

TEST(A5Hidden, NeeDepthCutTracesAtMostTwoKPlusOneRays) {
  const Scene furnace = make_furnace(0.5, 1.0);
  Rng rng(19, 19);
  RayCount count;
  estimate_nee_radiance(furnace, {Vec3(0.0), {0.0, 0.0, 1.0}}, nee_depth_cut(4), rng, count);
  EXPECT_EQ(count.rays, 9u) << "k = 4: 5 closest-hit queries and one shadow ray at each of the 4 vertices before the cut";
}

}  // namespace
}  // namespace mcrt::testing::assignment
