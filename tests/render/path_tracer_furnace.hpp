#pragma once
// Path-tracer samples in the furnace, shared by the furnace checks (tests/checks/) and by the
// unit tests that show those checks reject the known-wrong tracers of path_tracer_known_bugs.hpp.
//
// In the furnace (albedo a, emission Le everywhere) the radiance after at most k bounces is
// Le (1 - a^(k+1)) / (1 - a) in every direction, with the variance furnace_radiance_variance
// (common/render/path_tracer.hpp). The z-test compares the mean of n paths with it, using that
// closed-form standard error sqrt(Var / n); n is large enough for the central limit theorem
// (every sample is bounded by Le (1 + 2a + ... + (2a)^k)).

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

struct FurnaceSetup {
  double albedo = 0.5;
  double emission = 1.0;
  int depth = 3;
};

/// n paths from the furnace's centre, path i in a uniformly random direction drawn from
/// stream (block, i) of `seed` (distinct blocks give independent sets);
/// `estimate(scene, ray, depth, rng, count)` is the tracer under test.
template <class Estimator>
RunningStats furnace_samples(const FurnaceSetup& setup, int n, std::uint64_t seed,
                             std::uint64_t block, Estimator&& estimate) {
  const Scene scene = make_furnace(setup.albedo, setup.emission);
  RunningStats samples;
  RayCount count;
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, stream_index(block, static_cast<std::uint64_t>(i)));
    const Ray ray{Vec3(0.0), sample_uniform_sphere(rng.uniform2())};
    samples.add(average(estimate(scene, ray, setup.depth, rng, count)));
  }
  return samples;
}

/// Two-sided z-test of the furnace mean against Le (1 - a^(k+1)) / (1 - a).
inline double furnace_mean_p_value(const FurnaceSetup& setup, const RunningStats& samples) {
  const double expected = furnace_radiance(setup.albedo, setup.emission, setup.depth);
  const double variance = furnace_radiance_variance(setup.albedo, setup.emission, setup.depth);
  return z_test_p_value(samples.mean(), expected,
                        std::sqrt(variance / static_cast<double>(samples.count())));
}

/// The furnace radiance of n paths of the chapter's tracer, one value (the channel mean) per
/// path, for the variance test.
inline std::vector<double> furnace_radiance_values(const FurnaceSetup& setup, int n,
                                                   std::uint64_t seed, std::uint64_t block) {
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(n));
  furnace_samples(setup, n, seed, block,
                  [&](const Scene& scene, const Ray& ray, int depth, Rng& rng, RayCount& count) {
                    const Color c = estimate_path_radiance(scene, ray, depth, rng, count);
                    values.push_back(average(c));
                    return c;
                  });
  return values;
}

/// The path tracer under test, as the callable furnace_samples takes.
inline Color chapter_path_tracer(const Scene& scene, const Ray& ray, int depth, Rng& rng,
                                 RayCount& count) {
  return estimate_path_radiance(scene, ray, depth, rng, count);
}

}  // namespace mcrt::testing
