// The path tracer on the fast layers gives the image of the same path loop on the plain layers
// (render/path_tracer_plain_layers.hpp): same seed, so the same streams and the same uniforms.
//
// The closest-hit searches return the plain loop's hit bit for bit (engines_differential_test),
// but cos_sin_two_pi can differ from std::cos and std::sin in the last bit, and so can the
// directions. A path's value depends on its directions only through the surfaces they reach
// (its weights are 2 rho cos(theta) with cos(theta) = u0), so a pixel is the same bit for bit
// unless one of its paths is sent past an edge to another surface by a last-bit change. So the
// test asks for both:
//  - nearly every pixel is exactly equal (a wrong sampler or search changes almost every pixel:
//    each pixel's 16 paths make 160 samplings and 176 searches);
//  - over the whole image, the paired differences have mean 0 (z-test at 1e-4, so this check
//    fails wrongly once in 10^4 runs): paths that part are both unbiased.

#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "stats/hypothesis.hpp"
#include "render/path_tracer_plain_layers.hpp"

using namespace mcrt;

namespace {

constexpr int k_depth = 10;
constexpr double k_false_failure_rate = 1e-4;

void expect_plain_image(const char* scene_name) {
  const Scene scene = make_scene(scene_name);
  const Camera camera(scene.camera, 96, 72);
  const RenderSettings settings{16, 0, 7, 2, nullptr};
  const Image fast = render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
                       return estimate_path_radiance(scene, ray, k_depth, rng, count);
                     }).image;
  const Image plain = render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
                        return mcrt::testing::plain_path_radiance(scene, ray, k_depth, rng, count);
                      }).image;

  const std::size_t n = plain.pixels.size();
  std::size_t agreeing = 0;
  double sum = 0.0, sum_squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = average(fast.pixels[i]), b = average(plain.pixels[i]);
    const double d = a - b;
    agreeing += d == 0.0;
    sum += d;
    sum_squares += d * d;
  }
  // At this seed all 6912 pixels are equal, in both scenes; 98% leaves room for the rare
  // parted path at other seeds, while a wrong layer, which changes nearly every pixel, fails.
  EXPECT_GE(static_cast<double>(agreeing), 0.98 * static_cast<double>(n)) << scene_name;
  const double mean = sum / static_cast<double>(n);
  const double variance = (sum_squares - sum * mean) / static_cast<double>(n - 1);
  if (variance > 0.0) {
    const double standard_error = std::sqrt(variance / static_cast<double>(n));
    EXPECT_GE(mcrt::testing::z_test_p_value(mean, 0.0, standard_error), k_false_failure_rate)
        << scene_name << ": mean difference " << mean << ", standard error " << standard_error;
  }
}

TEST(PlainLayersTest, CornellSpheresImageIsThePlainLoopsImage) {
  expect_plain_image("cornell-spheres");
}

TEST(PlainLayersTest, CornellImageIsThePlainLoopsImage) { expect_plain_image("cornell"); }

}  // namespace
