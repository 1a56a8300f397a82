// The recursive N^k estimator: exact ray counts, the depth cut, bounds and determinism, its
// furnace closed forms, and the power of the furnace checks (tests/render/recursive_estimator_checks.cpp)
// against the wrong answers of tests/render/recursive_estimator_known_bugs.hpp.

#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "geometry/camera.hpp"
#include "render/recursive_estimator_known_bugs.hpp"
#include "render/recursive_estimator.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "stats/hypothesis.hpp"
#include "render/recursive_estimator_furnace.hpp"

namespace mcrt {
namespace {

// (N^(k+1) - 1) / (N - 1) by repeated multiplication, for small N and k.
std::uint64_t geometric_sum(std::uint64_t n, int k) {
  std::uint64_t power = 1;
  for (int j = 0; j <= k; ++j) power *= n;
  return (power - 1) / (n - 1);
}

RenderResult render_recursive(const Scene& scene, int width, int height, int spp,
                              const RecursiveSettings& recursion, int threads = 1,
                              std::uint64_t seed = 7) {
  const Camera camera(scene.camera, width, height);
  const RenderSettings settings{spp, 0, seed, threads, nullptr};
  return render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
    return incident_radiance(scene, ray, 0, recursion, rng, count);
  });
}

TEST(MaxRaysPerSample, IsTheGeometricSum) {
  for (int n = 2; n <= 9; ++n)
    for (int k = 0; k <= 8; ++k)
      EXPECT_EQ(max_rays_per_sample(n, k), geometric_sum(static_cast<std::uint64_t>(n), k))
          << "N = " << n << ", k = " << k;
  for (int k = 0; k <= 100; ++k) EXPECT_EQ(max_rays_per_sample(1, k), k + 1u);
}

TEST(MaxRaysPerSample, SaturatesInsteadOfOverflowing) {
  constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  EXPECT_EQ(max_rays_per_sample(2, 62), (std::uint64_t{1} << 63) - 1);  // 2^63 - 1, exact
  EXPECT_EQ(max_rays_per_sample(2, 63), max);  // 2^64 - 1: exactly the largest value
  EXPECT_EQ(max_rays_per_sample(2, 64), max);  // 2^65 - 1: saturated
  EXPECT_EQ(max_rays_per_sample(1000, 10), max);
  EXPECT_EQ(max_rays_per_sample(65536, 64), max);
}

// No ray leaves the furnace, so every sample traces 1 + N + ... + N^k rays exactly.
TEST(IncidentRadiance, FurnaceRayCountsEqualThePrediction) {
  const Scene furnace = make_furnace(0.5, 1.0);
  const int width = 5, height = 4, spp = 3;
  for (int n : {1, 2, 3, 5})
    for (int k : {0, 1, 2, 4}) {
      const RenderResult r = render_recursive(furnace, width, height, spp, {n, k});
      const auto samples = static_cast<std::uint64_t>(width * height * spp);
      EXPECT_EQ(r.rays, samples * max_rays_per_sample(n, k)) << "N = " << n << ", k = " << k;
    }
}

// Depth 0 is the cut itself: the emitted light of the first hit, one ray, no random numbers.
TEST(IncidentRadiance, DepthZeroReturnsTheEmission) {
  const Scene furnace = make_furnace(0.7, 2.5);
  Rng rng(3, 4), untouched(3, 4);
  RayCount count;
  const Color L = incident_radiance(furnace, {Vec3(0.0), {0.0, 0.6, 0.8}}, 0, {8, 0}, rng, count);
  EXPECT_EQ(L, Color(2.5));
  EXPECT_EQ(count.rays, 1u);
  EXPECT_EQ(rng.next_bits(), untouched.next_bits());
}

// The recursion stops at max_depth whatever depth it is called with there.
TEST(IncidentRadiance, CallAtTheCutDepthReturnsTheEmission) {
  const Scene furnace = make_furnace(0.7, 2.5);
  Rng rng(3, 5);
  RayCount count;
  EXPECT_EQ(incident_radiance(furnace, {Vec3(0.0), {1.0, 0.0, 0.0}}, 3, {4, 3}, rng, count),
            Color(2.5));
  EXPECT_EQ(count.rays, 1u);
}

// A ray out of the Cornell box's open front meets nothing: no light, one ray, at any depth.
TEST(IncidentRadiance, EscapingRayBringsNoLight) {
  const Scene box = make_cornell_box();
  const Ray outwards{box.camera.eye, {0.0, 0.0, -1.0}};  // the camera looks along +z
  for (int k : {0, 3}) {
    Rng rng(1, 2);
    RayCount count;
    EXPECT_EQ(incident_radiance(box, outwards, 0, {4, k}, rng, count), Color(0.0));
    EXPECT_EQ(count.rays, 1u);
  }
}

// With albedo 0 every branch weighs 0: the emission exactly, yet the recursion still traces
// every ray of the tree (the pseudo-code does not look at the BRDF before recursing).
TEST(IncidentRadiance, BlackFurnaceGivesTheEmissionExactly) {
  const Scene furnace = make_furnace(0.0, 1.25);
  Rng rng(9, 1);
  RayCount count;
  EXPECT_EQ(incident_radiance(furnace, {Vec3(0.0), {0.0, 0.0, -1.0}}, 0, {3, 3}, rng, count),
            Color(1.25));
  EXPECT_EQ(count.rays, max_rays_per_sample(3, 3));
}

// Every furnace sample lies in [Le, Le (1 + 2a + ... + (2a)^k)]: a branch weighs
// 2 a cos(theta) in [0, 2a]. A missing 1/N or 1/pdf would break the upper bound.
TEST(IncidentRadiance, FurnaceSamplesStayWithinTheirBounds) {
  const double a = 0.8, le = 1.5;
  for (int n : {1, 2, 3})
    for (int k : {1, 3}) {
      double upper = 0.0, weight = 1.0;
      for (int j = 0; j <= k; ++j, weight *= 2.0 * a) upper += le * weight;
      const auto samples = testing::recursive_furnace_samples({a, le, n, k}, 2000, 11,
                                                              static_cast<std::uint64_t>(n));
      for (double x : samples) {
        ASSERT_GE(x, le);
        ASSERT_LE(x, upper * (1.0 + 1e-12));  // round-off in the sum of weights
      }
    }
}

// With N = 1 the path cut at k + 1 extends the path cut at k (same random numbers), and light
// only adds up: every pixel of every channel is at least as bright one bounce deeper. This is
// what makes the chapter's missing-light curve smooth.
TEST(IncidentRadiance, SinglePathBrightensMonotonicallyWithDepth) {
  const Scene box = make_cornell_box();
  Image previous = render_recursive(box, 12, 9, 2, {1, 0}).image;
  for (int k = 1; k <= 4; ++k) {
    const Image image = render_recursive(box, 12, 9, 2, {1, k}).image;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) ASSERT_GE(image.pixels[i][c], previous.pixels[i][c]);
    previous = image;
  }
}

// In the open Cornell box paths escape: never more rays than predicted, and some fewer.
TEST(IncidentRadiance, CornellRaysNeverExceedThePrediction) {
  const Scene box = make_cornell_box();
  for (int n : {1, 3})
    for (int k : {0, 2}) {
      const RenderResult r = render_recursive(box, 10, 8, 2, {n, k});
      const std::uint64_t predicted = 10u * 8u * 2u * max_rays_per_sample(n, k);
      if (k == 0) {
        EXPECT_EQ(r.rays, predicted);  // the camera rays themselves
      } else {
        EXPECT_LT(r.rays, predicted);
        EXPECT_GT(r.rays, 10u * 8u * 2u);
      }
    }
}

TEST(IncidentRadiance, SameSeedSameImageWhateverTheThreads) {
  const Scene box = make_cornell_box();
  const RenderResult one = render_recursive(box, 16, 12, 2, {2, 2}, 1, 5);
  const RenderResult three = render_recursive(box, 16, 12, 2, {2, 2}, 3, 5);
  EXPECT_EQ(one.rays, three.rays);
  EXPECT_EQ(one.image.pixels, three.image.pixels);
  const RenderResult other_seed = render_recursive(box, 16, 12, 2, {2, 2}, 1, 6);
  EXPECT_NE(one.image.pixels, other_seed.image.pixels);
}

TEST(FurnaceMoments, MatchTheirDerivationsAtSmallDepth) {
  const double a = 0.6;
  const FurnaceMoments m0 = furnace_moments(a, 3, 0);
  EXPECT_EQ(m0.mean, 1.0);
  EXPECT_EQ(m0.variance, 0.0);
  // k = 1: L = 1 + (1/N) sum w_i with Var[w] = 4a^2/3 - a^2 = a^2/3.
  for (int n : {1, 2, 5}) {
    const FurnaceMoments m1 = furnace_moments(a, n, 1);
    EXPECT_DOUBLE_EQ(m1.mean, 1.0 + a);
    EXPECT_DOUBLE_EQ(m1.variance, a * a / (3.0 * n));
  }
  // k = 2, N = 1: L = 1 + w1 (1 + w2), expanded directly:
  // Var = E[w1^2] (1 + 2a + E[w2^2]) - (a + a^2)^2 = a^2/3 + 2a^3/3 + 7a^4/9.
  const FurnaceMoments m2 = furnace_moments(a, 1, 2);
  EXPECT_DOUBLE_EQ(m2.mean, 1.0 + a + a * a);
  EXPECT_DOUBLE_EQ(m2.variance, a * a / 3.0 + 2.0 * a * a * a / 3.0 + 7.0 * std::pow(a, 4) / 9.0);
  // The series: E = (1 - a^(k+1)) / (1 - a).
  EXPECT_DOUBLE_EQ(furnace_moments(a, 4, 9).mean, (1.0 - std::pow(a, 10)) / (1.0 - a));
}

// The furnace checks must catch the bugs they are there for. Same samples as a check, tested
// against what a wrong estimator would converge to; each must be rejected at alpha = 1e-4.
TEST(FurnaceChecks, RejectWrongExpectations) {
  const testing::RecursiveFurnace f{0.5, 1.0, 2, 3};
  const auto samples = testing::recursive_furnace_samples(f, 20000, 20261122, 403);
  const auto mean_p = [&](auto moments) {
    return testing::mean_p_value(samples, moments(0.5, 2, 3).mean);
  };
  const auto variance_p = [&](auto moments) {
    return testing::variance_z_test_p_value(samples, moments(0.5, 2, 3).variance);
  };
  EXPECT_GE(mean_p(furnace_moments), 1e-4);
  EXPECT_LT(mean_p(testing::furnace_moments_one_bounce_short), 1e-4);
  EXPECT_LT(mean_p(testing::furnace_moments_albedo_two_percent_high), 1e-4);
  EXPECT_GE(variance_p(furnace_moments), 1e-4);
  EXPECT_LT(variance_p(testing::furnace_moments_one_shared_branch), 1e-4);
  EXPECT_LT(variance_p(testing::furnace_moments_variance_ten_percent_high), 1e-4);
}

}  // namespace
}  // namespace mcrt
