// The image loop with a sampler (render/sampled_render.hpp): with independent samples it is
// render() bit for bit (so chapter 05's default images are unchanged); with jittered and
// sobol it is unbiased in the furnace (a t-test of the pixels' mean against the closed form,
// which rejects an unscrambled Sobol' net), stratification shrinks the variance the furnace's
// closed form predicts for independent samples, and the image does not depend on --threads.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/sampled_render.hpp"
#include "render/scene.hpp"
#include "sampling/point_sets.hpp"
#include "stats/hypothesis.hpp"

using namespace mcrt;
using mcrt::testing::z_test_p_value;

namespace {

bool same_bits(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

RenderResult render_paths(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                          PathSampler sampler, int depth) {
  return render_sampled(camera, settings, sampler, [&](const Ray& ray, auto& rng, RayCount& count) {
    return estimate_path_radiance(scene, ray, depth, rng, count);
  });
}

// Known wrong: the plain Sobol' net, the same deterministic points for every pixel and every
// bounce (no scramble, no padding). Each point is not uniform, so the estimate is biased.
struct UnscrambledSobolSample {
  std::uint32_t count, index;
  Vec2 uniform2() const {
    const SobolPoints points{count, 0, SobolScramble::none};
    return {points(index, 0), points(index, 1)};
  }
  double uniform() const { return uniform2().x; }
};

RenderResult render_unscrambled(const Scene& scene, const Camera& camera,
                                const RenderSettings& settings, int depth) {
  return render_rows(camera, settings, [&](int y, Color* row, RayCount& rays, std::uint64_t&) {
    for (int x = 0; x < camera.width(); ++x) {
      Color sum(0.0);
      for (int s = 0; s < settings.spp; ++s) {
        UnscrambledSobolSample sample{static_cast<std::uint32_t>(settings.spp),
                                      static_cast<std::uint32_t>(s)};
        sum += estimate_path_radiance(scene, camera.generate_ray(x, y, sample.uniform2()), depth,
                                      sample, rays);
      }
      row[x] = sum / static_cast<double>(settings.spp);
    }
  });
}

struct PixelStats {
  double mean = 0.0, variance = 0.0;  // over the pixels, of each pixel's channel mean
  std::size_t n = 0;
};

PixelStats pixel_stats(const Image& image) {
  PixelStats stats;
  stats.n = image.pixels.size();
  for (const Color& c : image.pixels) stats.mean += average(c);
  stats.mean /= static_cast<double>(stats.n);
  for (const Color& c : image.pixels) stats.variance += std::pow(average(c) - stats.mean, 2);
  stats.variance /= static_cast<double>(stats.n - 1);
  return stats;
}

// The furnace: every pixel's radiance has the closed-form mean Le (1 + a + ... + a^k); the
// pixels are independent randomisations (keys of their own), so their mean is tested against
// it with the standard error from their spread (1536 pixels: the normal approximation holds).
constexpr double k_albedo = 0.5;
constexpr int k_width = 48, k_height = 32;
// Two-sided p below this rejects: a false failure once in 10^6 runs per case.
constexpr double k_alpha = 1e-6;

double furnace_p_value(const Image& image, int depth) {
  const PixelStats stats = pixel_stats(image);
  return z_test_p_value(stats.mean, furnace_radiance(k_albedo, 1.0, depth),
                        std::sqrt(stats.variance / static_cast<double>(stats.n)));
}

TEST(SampledRenderTest, IndependentIsRenderBitForBit) {
  const Scene scene = make_scene("cornell");
  const Camera camera(scene.camera, 13, 9);
  for (std::uint64_t first : {0ull, 5ull}) {
    const RenderSettings settings{3, first, 21, 2, nullptr};
    const RenderResult lecture =
        render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
          return estimate_path_radiance(scene, ray, 4, rng, count);
        });
    const RenderResult sampled = render_paths(scene, camera, settings, PathSampler::independent, 4);
    EXPECT_TRUE(same_bits(lecture.image, sampled.image));
    EXPECT_EQ(lecture.rays, sampled.rays);
  }
}

TEST(SampledRenderTest, JitteredAndSobolAreUnbiasedInTheFurnace) {
  const Scene scene = make_furnace(k_albedo, 1.0);
  const Camera camera(scene.camera, k_width, k_height);
  for (PathSampler sampler : {PathSampler::jittered, PathSampler::sobol})
    for (int spp : {4, 6}) {  // a power of two and not
      const RenderSettings settings{spp, 0, 3, 2, nullptr};
      const RenderResult result = render_paths(scene, camera, settings, sampler, 3);
      EXPECT_GT(furnace_p_value(result.image, 3), k_alpha) << name_of(sampler) << " spp " << spp;
      EXPECT_EQ(result.rays, 4u * k_width * k_height * spp);  // the furnace never lets a path out
    }
}

// The same test rejects the plain net: its points are not uniform (at 4 points the cosines
// of dimension 0 are 0, 1/2, 3/4, 1/4, mean 3/8, not 1/2), and every pixel repeats them.
TEST(SampledRenderTest, FurnaceTestRejectsAnUnscrambledNet) {
  const Scene scene = make_furnace(k_albedo, 1.0);
  const Camera camera(scene.camera, k_width, k_height);
  const RenderResult result = render_unscrambled(scene, camera, {4, 0, 3, 2, nullptr}, 3);
  EXPECT_LT(furnace_p_value(result.image, 3), k_alpha);
}

// Direct light only (depth 1) in the furnace: L = Le (1 + 2 a cos theta), cos theta = u_x of
// bounce 0's set. Independent samples: Var[pixel] = Var[L] / spp (the closed form). Stratified
// in x into c strata, the mean of u_x has variance 1/c^2 of that: c = 4 columns at 16 spp for
// jittered (1/16), 16 for sobol (1/256). The bound 0.2 sits far above both and far below 1;
// 1536 pixels estimate the variance to about 4%.
TEST(SampledRenderTest, StratificationShrinksTheVarianceOfDirectLight) {
  const Scene scene = make_furnace(k_albedo, 1.0);
  const Camera camera(scene.camera, k_width, k_height);
  const int spp = 16;
  const double independent_variance = furnace_radiance_variance(k_albedo, 1.0, 1) / spp;
  for (PathSampler sampler : {PathSampler::jittered, PathSampler::sobol}) {
    const RenderResult result = render_paths(scene, camera, {spp, 0, 8, 2, nullptr}, sampler, 1);
    EXPECT_LT(pixel_stats(result.image).variance, 0.2 * independent_variance) << name_of(sampler);
  }
  const RenderResult independent =
      render_paths(scene, camera, {spp, 0, 8, 2, nullptr}, PathSampler::independent, 1);
  EXPECT_GT(pixel_stats(independent.image).variance, 0.8 * independent_variance);
}

TEST(SampledRenderTest, ImagesDoNotDependOnThreadsAndBlocksAreIndependent) {
  const Scene scene = make_scene("cornell-spheres");
  const Camera camera(scene.camera, 17, 11);
  for (PathSampler sampler : {PathSampler::jittered, PathSampler::sobol}) {
    const RenderResult one = render_paths(scene, camera, {8, 0, 4, 1, nullptr}, sampler, 5);
    const RenderResult two = render_paths(scene, camera, {8, 0, 4, 2, nullptr}, sampler, 5);
    EXPECT_TRUE(same_bits(one.image, two.image)) << name_of(sampler);
    EXPECT_EQ(one.rays, two.rays);
    const RenderResult later = render_paths(scene, camera, {8, 8, 4, 2, nullptr}, sampler, 5);
    EXPECT_FALSE(same_bits(one.image, later.image)) << name_of(sampler);
  }
}

}  // namespace
