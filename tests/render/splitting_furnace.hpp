#pragma once
// Split paths in the furnace, and the tests run on them, shared by the statistical checks
// (tests/render/splitting_checks.cpp) and by the unit tests that show those checks reject the
// known-wrong variants of tests/render/splitting_known_bugs.hpp.
//
// In the furnace (albedo a < 1, emission Le everywhere, every ray hits) with fixed q and
// splitting depth s <= d: the mean is Le / (1 - a), the variance furnace_splitting_variance and
// the rays furnace_splitting_mean_rays (common/render/splitting.hpp). The rays' variance: the
// first s vertices are traced in full (1 + n + ... + n^(s-1) rays), then each of the n^s tails
// traces d - s + 1 rays and a geometric G more (P(G = g) = q^g (1 - q)), independently:
//   Var[rays] = n^s Var[G] = n^s q / (1 - q)^2.

#include <cmath>
#include <cstdint>
#include <vector>

#include "integration/statistics.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "render/splitting.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

struct SplittingFurnaceSetup {
  double albedo = 0.5;
  double emission = 1.0;
  Roulette roulette;  // fixed q
  Splitting splitting;
};

/// The estimator under test, as splitting_furnace_paths takes it.
inline Color chapter_splitting(const Scene& scene, const Ray& ray, const Roulette& roulette,
                               const Splitting& splitting, Rng& rng, RayCount& count) {
  return estimate_path_radiance_splitting(scene, ray, roulette, splitting, rng, count);
}

/// n split paths of `estimate` from the furnace's centre, path i from stream (block, i) of
/// `seed`, on `threads` threads (the paths are the same whatever the count).
template <class Estimator>
std::vector<FurnacePath> splitting_furnace_paths(const SplittingFurnaceSetup& setup, int n,
                                                 std::uint64_t seed, std::uint64_t block,
                                                 Estimator&& estimate, int threads = 1) {
  const Scene scene = make_furnace(setup.albedo, setup.emission);
  return trace_furnace_paths(static_cast<std::uint64_t>(n), seed, block, threads,
                             [&](const Ray& ray, Rng& rng, RayCount& count) {
                               return estimate(scene, ray, setup.roulette, setup.splitting, rng,
                                               count);
                             });
}

/// Var[rays] of a split path in the furnace: n^s q / (1 - q)^2.
inline double furnace_splitting_rays_variance(const SplittingFurnaceSetup& setup) {
  const double q = setup.roulette.q;
  return std::pow(setup.splitting.n, setup.splitting.depth) * q / ((1.0 - q) * (1.0 - q));
}

/// Two-sided z-test of the mean radiance against Le / (1 - a), its standard error from the
/// closed-form variance (the setups keep q above 4a^2/3 and the third moment finite, so the
/// mean of the n paths is normal to well within the test's level).
inline double splitting_mean_p_value(const SplittingFurnaceSetup& setup,
                                     const std::vector<FurnacePath>& paths) {
  RunningStats radiance;
  for (const FurnacePath& path : paths) radiance.add(path.radiance);
  const double variance =
      furnace_splitting_variance(setup.albedo, setup.emission, setup.roulette.min_depth,
                                 setup.roulette.q, setup.splitting);
  return z_test_p_value(radiance.mean(), furnace_radiance_untruncated(setup.albedo, setup.emission),
                        std::sqrt(variance / static_cast<double>(radiance.count())));
}

/// Two-sided z-test of the mean rays per path against furnace_splitting_mean_rays, its standard
/// error from the rays' closed-form variance (a sum of geometric lengths: every moment finite).
inline double splitting_rays_p_value(const SplittingFurnaceSetup& setup,
                                     const std::vector<FurnacePath>& paths) {
  RunningStats rays;
  for (const FurnacePath& path : paths) rays.add(static_cast<double>(path.rays));
  return z_test_p_value(
      rays.mean(),
      furnace_splitting_mean_rays(setup.roulette.min_depth, setup.roulette.q, setup.splitting),
      std::sqrt(furnace_splitting_rays_variance(setup) / static_cast<double>(rays.count())));
}

inline std::vector<double> splitting_radiance_values(const std::vector<FurnacePath>& paths) {
  std::vector<double> values;
  values.reserve(paths.size());
  for (const FurnacePath& path : paths) values.push_back(path.radiance);
  return values;
}

}  // namespace mcrt::testing
