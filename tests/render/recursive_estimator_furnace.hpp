#pragma once
// Samples of the recursive N^k estimator in the furnace, shared by the furnace checks
// (tests/render/recursive_estimator_checks.cpp) and by the unit tests that show those checks reject the
// wrong closed forms of tests/render/recursive_estimator_known_bugs.hpp.
//
// In the furnace (albedo a, emission Le everywhere) incidentRadiance cut at depth k has, in
// every direction and for every N, mean Le (1 + a + ... + a^k) and the variance of
// furnace_moments (common/render/recursive_estimator.hpp). Every sample lies in
// [Le, Le (1 + 2a + ... + (2a)^k)] (each branch weight 2 a cos(theta) is at most 2a), so all
// its moments are finite and the central limit theorem applies to means of many samples.

#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

struct RecursiveFurnace {
  double albedo = 0.5;
  double emission = 1.0;
  int branching = 1;  ///< N
  int depth = 1;      ///< k
};

/// n samples of incidentRadiance from the furnace's centre; sample i looks in a uniformly random
/// direction and draws from stream stream_index(stream_base, i) of `seed`.
inline std::vector<double> recursive_furnace_samples(const RecursiveFurnace& f, int n,
                                                     std::uint64_t seed,
                                                     std::uint64_t stream_base) {
  const Scene scene = make_furnace(f.albedo, f.emission);
  const RecursiveSettings settings{f.branching, f.depth};
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(n));
  RayCount count;
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, stream_index(stream_base, static_cast<std::uint64_t>(i)));
    const Ray ray{Vec3(0.0), sample_uniform_sphere(rng.uniform2())};
    samples.push_back(average(incident_radiance(scene, ray, 0, settings, rng, count)));
  }
  return samples;
}

/// Two-sided one-sample t-test of the samples' mean against `expected`, the variance taken
/// from the samples.
inline double mean_p_value(const std::vector<double>& samples, double expected) {
  RunningStats stats;
  for (double x : samples) stats.add(x);
  return t_test_p_value(stats.mean(), stats.variance(), stats.count(), expected);
}

}  // namespace mcrt::testing
