#pragma once
// Samples of the importance-sampled path tracer (common/render/importance_path_tracer.hpp),
// shared by its statistical checks (tests/render/importance_path_tracer_checks.cpp) and by the
// unit tests that show those checks reject the known-wrong tracers
// (tests/render/importance_path_tracer_test.cpp).
//
// Two tests of unbiasedness:
//  - the furnace: the mean of n paths against Le (1 - a^(k+1)) / (1 - a), with the closed-form
//    standard error sqrt(Var / n) of furnace_radiance_variance(pdf, ...), for the pdfs whose
//    variance is finite; for the cosine pdf every path must equal the closed form;
//  - two parallel plates: a tracer under test against chapter 05's estimate_path_radiance, a
//    two-sample z-test of their means. A point of one plate sees the other under
//    cos(theta) >= 1/sqrt(3) (the plates are unit squares one apart), and the rest of the
//    hemisphere is empty: the weight f_r cos / p of every bounce that still gathers light is
//    bounded for cos^m at any m (for m = 8 by 2 a (1/sqrt 3)^-7 / 9 = 10.4 a; the grazing pdf's
//    a pi cos / (2 sin) is not bounded near the normal, but its square has a finite mean), so
//    the variance is finite for every pdf, which the furnace does not give for m >= 3.

#include <cmath>
#include <cstdint>

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "stats/hypothesis.hpp"
#include "render/path_tracer_furnace.hpp"

namespace mcrt::testing {

/// The tracer under test with a fixed pdf, as furnace_samples and plate_samples take it.
inline auto importance_tracer(HemispherePdf pdf) {
  return [pdf](const Scene& scene, const Ray& ray, int depth, Rng& rng, RayCount& count) {
    return estimate_importance_path_radiance(scene, ray, depth, pdf, rng, count);
  };
}

/// Two-sided z-test of the furnace mean with the closed-form standard error of `pdf`'s tracer.
inline double importance_furnace_mean_p_value(const FurnaceSetup& setup, const HemispherePdf& pdf,
                                              const RunningStats& samples) {
  const double expected = furnace_radiance(setup.albedo, setup.emission, setup.depth);
  const double variance = furnace_radiance_variance(pdf, setup.albedo, setup.emission, setup.depth);
  return z_test_p_value(samples.mean(), expected,
                        std::sqrt(variance / static_cast<double>(samples.count())));
}

/// The largest |L - Le (1 - a^(k+1)) / (1 - a)| over n furnace paths, relative to the closed form.
template <class Estimator>
double furnace_largest_relative_deviation(const FurnaceSetup& setup, int n, std::uint64_t seed,
                                          std::uint64_t block, Estimator&& estimate) {
  const double expected = furnace_radiance(setup.albedo, setup.emission, setup.depth);
  double largest = 0.0;
  furnace_samples(setup, n, seed, block,
                  [&](const Scene& scene, const Ray& ray, int depth, Rng& rng, RayCount& count) {
                    const Color c = estimate(scene, ray, depth, rng, count);
                    largest = std::max(largest, std::abs(average(c) - expected) / expected);
                    return c;
                  });
  return largest;
}

/// Two unit squares facing each other one apart (y = 0 and y = 1), both diffuse and emitting:
/// light bounces between them, escapes at the sides.
inline Scene make_parallel_plates() {
  Scene scene;
  scene.name = "parallel-plates";
  const auto lower = scene.add_material({Color(0.6, 0.5, 0.4), Color(0.5)});
  const auto upper = scene.add_material({Color(0.5), Color(1.0, 0.8, 0.6)});
  scene.add_quad({{-0.5, 0.0, -0.5}, {0, 0, 1}, {1, 0, 0}, lower});
  scene.add_quad({{-0.5, 1.0, -0.5}, {0, 0, 1}, {1, 0, 0}, upper});
  return scene;
}

inline constexpr int k_plate_depth = 4;

/// n paths between the plates: straight down from a uniform point of the mid-plane square, so
/// every path first hits the lower plate (its emission is the same in every sample: no noise)
/// and all the variance is the bounces'. Path i draws from stream (block, i) of `seed`; one
/// value (the channel mean) per path.
template <class Estimator>
RunningStats plate_samples(int n, std::uint64_t seed, std::uint64_t block, Estimator&& estimate) {
  const Scene scene = make_parallel_plates();
  RunningStats samples;
  RayCount count;
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, stream_index(block, static_cast<std::uint64_t>(i)));
    const Vec2 p = rng.uniform2();
    const Ray ray{{p.x - 0.5, 0.5, p.y - 0.5}, {0.0, -1.0, 0.0}};
    samples.add(average(estimate(scene, ray, k_plate_depth, rng, count)));
  }
  return samples;
}

/// Two-sided two-sample z-test: the tracer under test against chapter 05's on the plates, n
/// paths each on disjoint streams (blocks 2 block and 2 block + 1), standard error from the
/// sample variances (finite for every pdf, see the top; n is large for the CLT).
template <class Estimator>
double plates_p_value(int n, std::uint64_t seed, std::uint64_t block, Estimator&& estimate) {
  const RunningStats ours = plate_samples(n, seed, 2 * block, estimate);
  const RunningStats chapter05 = plate_samples(n, seed, 2 * block + 1, chapter_path_tracer);
  const double standard_error =
      std::sqrt(ours.variance() / static_cast<double>(ours.count()) +
                chapter05.variance() / static_cast<double>(chapter05.count()));
  return z_test_p_value(ours.mean() - chapter05.mean(), 0.0, standard_error);
}

}  // namespace mcrt::testing
