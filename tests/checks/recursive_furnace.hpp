#pragma once
// Samples of the recursive N^k estimator in the furnace, shared by the furnace checks and by
// the unit tests that show those checks reject wrong closed forms.
//
// In the furnace (albedo a, emission Le everywhere) incidentRadiance cut at depth k has, in
// every direction and for every N, mean Le (1 + a + ... + a^k) and the variance of
// furnace_moments (common/recursive_estimator.hpp). Every sample lies in
// [Le, Le (1 + 2a + ... + (2a)^k)] (each branch weight 2 a cos(theta) is at most 2a), so all
// its moments are finite and the central limit theorem applies to means of many samples.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
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
    const Vec2 u = rng.uniform2();
    const double z = 1.0 - 2.0 * u.x, r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Ray ray{Vec3(0.0), {r * std::cos(k_two_pi * u.y), r * std::sin(k_two_pi * u.y), z}};
    samples.push_back(average(incident_radiance(scene, ray, 0, settings, rng, count)));
  }
  return samples;
}

/// Two-sided one-sample t-test of the samples' mean against `expected`, the variance taken
/// from the samples.
inline double mean_p_value(const std::vector<double>& samples, double expected) {
  RunningStats stats;
  for (double x : samples) stats.add(x);
  return stats::t_test_p_value(stats.mean(), stats.variance(), stats.count(), expected);
}

/// Two-sided z-test of the sample variance s^2 against `expected`, on the log scale. s^2 is a
/// mean of squared deviations, so for large n it is normal with variance
/// sigma^4 (kurtosis - (n-3)/(n-1)) / n, and by the delta method log(s^2) is normal with
/// variance (kurtosis - (n-3)/(n-1)) / n. The kurtosis mu4 / s^4 is estimated from the same
/// samples; being scale-free, it hardly moves with s^2, whereas an estimated standard error of
/// s^2 itself shrinks when s^2 comes out low, which made the plain z-test reject too often.
inline double variance_p_value(const std::vector<double>& samples, double expected) {
  RunningStats stats;
  for (double x : samples) stats.add(x);
  const double n = static_cast<double>(samples.size()), s2 = stats.variance();
  double mu4 = 0.0;
  for (double x : samples) mu4 += std::pow(x - stats.mean(), 4);
  mu4 /= n;
  if (!(s2 > 0.0) || !(expected > 0.0)) return s2 == expected ? 1.0 : 0.0;
  const double kurtosis = mu4 / (s2 * s2);
  const double variance_of_log_s2 = (kurtosis - (n - 3.0) / (n - 1.0)) / n;
  return stats::z_test_p_value(std::log(s2), std::log(expected), std::sqrt(variance_of_log_s2));
}

}  // namespace mcrt::testing
