// Correlation between samples that must be independent (issue #17, part 5):
//  - the samples of neighbouring pixels, and the different samples of one pixel, as the render
//    loop (common/render/render.hpp) keys them, in the furnace, where every sample of every
//    pixel has the same known mean and variance (furnace_radiance, furnace_radiance_variance)
//    and, with independent streams, no correlation at all;
//  - the streams of adjacent seeds and adjacent stream indices, beyond the first draws that
//    rng_neighbouring_seeds_and_streams_are_independent (core/rng_checks.cpp) looks at: draws 8 to
//    39 against the same draw and its neighbours of the next generator (lags -1, 0, +1), and
//    draws 1000 to 1007.
// The test statistics are in tests/render/render_correlation.hpp. Every check is designed for a
// false-failure rate alpha = 1e-4.

#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "stats/check.hpp"
#include "render/render_correlation.hpp"

namespace {

using namespace mcrt;

constexpr double k_albedo = 0.5, k_emission = 1.0;
constexpr int k_depth = 3;

// One value (the channel mean) per pixel of a furnace render at 1 sample per pixel, sample
// index `sample`, through the render loop every chapter uses.
std::vector<double> furnace_pixel_values(int width, int height, std::uint64_t seed,
                                         std::uint64_t sample) {
  const Scene scene = make_furnace(k_albedo, k_emission);
  const Camera camera(scene.camera, width, height);
  RenderSettings settings;
  settings.spp = 1;
  settings.first_sample = sample;
  settings.seed = seed;
  const RenderResult result =
      render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
        return estimate_path_radiance(scene, ray, k_depth, rng, count);
      });
  std::vector<double> values;
  values.reserve(result.image.pixels.size());
  for (const Color& c : result.image.pixels) values.push_back(average(c));
  return values;
}

// Right, lower and both diagonal neighbours over a 128 x 128 furnace image: four Z statistics
// of about 16 000 pairs each, chi-square with 4 dof. A correlation of 0.05 between
// neighbours gives Z = 6.4, p ~ 1e-8. False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(neighbouring_pixels_samples_are_uncorrelated, 1e-4) {
  constexpr int k_side = 128;
  const std::vector<double> values = furnace_pixel_values(k_side, k_side, seed, 0);
  return mcrt::testing::neighbour_correlation_p_value(
      values, k_side, k_side, furnace_radiance(k_albedo, k_emission, k_depth),
      furnace_radiance_variance(k_albedo, k_emission, k_depth));
}

// Samples 0..3 of every pixel of a 96 x 96 furnace image (four renders with first_sample 0..3,
// the streams (pixel, s)): six Z statistics of 9216 pairs each, chi-square with 6 dof. A
// correlation of 0.05 between a pixel's samples gives Z = 4.8. False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(samples_of_one_pixel_are_uncorrelated, 1e-4) {
  constexpr int k_side = 96, k_samples = 4;
  std::vector<std::vector<double>> samples;
  for (int s = 0; s < k_samples; ++s)
    samples.push_back(furnace_pixel_values(k_side, k_side, seed, static_cast<std::uint64_t>(s)));
  return mcrt::testing::sample_correlation_p_value(samples,
                                                   furnace_radiance(k_albedo, k_emission, k_depth),
                                                   furnace_radiance_variance(k_albedo, k_emission,
                                                                             k_depth));
}

// Uniforms of generator a against those of its neighbour b (next seed, or next stream) over
// S = 20 000 streams: for draw j in 8..39 and lag d in {-1, 0, +1}, Z = 12 sum (u_j - 1/2)
// (v_{j+d} - 1/2) / sqrt(S) (Var u = 1/12); and for draws 1000..1007, lag 0. The 2 x 104
// statistics are uncorrelated under independence: chi-square with 208 dof. A correlation of
// 0.1 at a single (j, d) gives Z = 14, chi-square ~ 400 on 208 dof: p ~ 1e-14.
// False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(adjacent_seeds_and_streams_are_independent_beyond_the_first_draws, 1e-4) {
  constexpr int k_streams = 20000, k_first = 8, k_last = 39, k_far = 1000, k_far_count = 8;
  constexpr int k_window = k_last + 2;  // draws 0..k_last + 1 (lag +1 of the last)
  constexpr int k_lags = 3;
  std::vector<double> seed_products((k_last - k_first + 1) * k_lags + k_far_count, 0.0);
  std::vector<double> stream_products(seed_products.size(), 0.0);
  const std::uint64_t first_stream = ((seed % 977) << 24) + 5;
  double u[k_window], v_seed[k_window], v_stream[k_window];
  for (int s = 0; s < k_streams; ++s) {
    const std::uint64_t stream = first_stream + static_cast<std::uint64_t>(s);
    Rng a(seed, stream), next_seed(seed + 1, stream), next_stream(seed, stream + 1);
    for (int j = 0; j < k_window; ++j) {
      u[j] = a.uniform() - 0.5;
      v_seed[j] = next_seed.uniform() - 0.5;
      v_stream[j] = next_stream.uniform() - 0.5;
    }
    std::size_t k = 0;
    for (int j = k_first; j <= k_last; ++j)
      for (int d = -1; d <= 1; ++d, ++k) {
        seed_products[k] += u[j] * v_seed[j + d];
        stream_products[k] += u[j] * v_stream[j + d];
      }
    for (int j = k_window; j < k_far; ++j) {  // skip to draw 1000 in all three
      a.next_bits();
      next_seed.next_bits();
      next_stream.next_bits();
    }
    for (int j = 0; j < k_far_count; ++j, ++k) {
      const double uf = a.uniform() - 0.5;
      seed_products[k] += uf * (next_seed.uniform() - 0.5);
      stream_products[k] += uf * (next_stream.uniform() - 0.5);
    }
  }
  mcrt::testing::ChiSquareSum sum;
  for (const auto* products : {&seed_products, &stream_products})
    for (double p : *products) sum.add(12.0 * p, k_streams);
  return sum.p_value();
}

}  // namespace
