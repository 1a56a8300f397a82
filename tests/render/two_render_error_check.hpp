#pragma once
// The two-render error of the chapters (common/render/two_render_error.hpp) against a closed
// form, shared by its statistical check (tests/render/path_tracer_checks.cpp) and by the unit
// test that shows the check rejects a known-wrong variant (tests/stats/known_bugs_test.cpp).
//
// In the furnace every sample of a pixel is a path of known variance Var[L]
// (furnace_radiance_variance), so a pixel of n samples has variance Var[L] / n, and for
// independent renders A and B, E[(A_p - B_p)^2 / 2] = Var[L] / n: the mean squared error the
// function under test reports must estimate it.
//
// The test: the reported error against Var[L] / n, a z-test whose standard error comes from
// the sample variance of d_p = (A_p - B_p)^2 / 2 over the P = 16384 independent pixels (the
// furnace is grey, so a pixel's three channels are one value). The d_p are skewed (about
// chi-square with 1 degree of freedom, skewness 2.8), but their mean over P pixels has
// skewness 2.8 / sqrt(P) = 0.02, so the normal tails hold the false-failure rate. A missing 1/2
// doubles the estimate: about 80 standard errors (relative standard error sqrt(2 / P) = 1.1%).

#include <cmath>
#include <cstdint>

#include "geometry/camera.hpp"
#include "integration/statistics.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

/// p-value of `mean_squared_error(A, B)` (an Image, Image -> double function) against
/// Var[L] / n for two furnace renders of n = 4 samples per pixel from disjoint sample ranges.
template <class MeanSquaredError>
double two_render_error_p_value(std::uint64_t seed, const MeanSquaredError& mean_squared_error) {
  const double albedo = 0.5, emission = 1.0;
  const int depth = 4, spp = 4;
  const Scene scene = make_furnace(albedo, emission);
  const Camera camera(scene.camera, 128, 128);
  auto render_samples = [&](std::uint64_t first_sample) {
    const RenderSettings settings{spp, first_sample, seed, 1, nullptr};
    return render(camera, settings,
                  [&](const Ray& ray, Rng& rng, RayCount& count) {
                    return estimate_path_radiance(scene, ray, depth, rng, count);
                  })
        .image;
  };
  const Image a = render_samples(0), b = render_samples(spp);

  RunningStats d;
  for (std::size_t p = 0; p < a.pixels.size(); ++p) {
    const double difference = a.pixels[p].r - b.pixels[p].r;
    d.add(difference * difference / 2.0);
  }
  const double expected = furnace_radiance_variance(albedo, emission, depth) / spp;
  const double standard_error = std::sqrt(d.variance() / static_cast<double>(d.count()));
  return z_test_p_value(mean_squared_error(a, b), expected, standard_error);
}

}  // namespace mcrt::testing
