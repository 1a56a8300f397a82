// Choosing a light uniformly or by power (render/light_choice.hpp): the choice's
// probabilities, the layout's promises (no light shadows the other, both above every floor
// point's horizon), both choices unbiased against the closed form (with a known-wrong weight
// rejected), and the variance each has where the page says it wins and loses.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "render/light_choice.hpp"
#include "stats/hypothesis.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

constexpr double k_alpha = 1e-4;  // the suite's false-failure rate, family-wise per test

TEST(LightChoiceTest, ProbabilitiesAreOneOverNOrThePowerShare) {
  const TwoLights scene;
  EXPECT_EQ(light_choice_probability(scene, LightChoice::uniform, 0), 0.5);
  EXPECT_EQ(light_choice_probability(scene, LightChoice::uniform, 1), 0.5);
  EXPECT_DOUBLE_EQ(light_choice_probability(scene, LightChoice::power, 0), 400.0 / 404.0);
  EXPECT_DOUBLE_EQ(light_choice_probability(scene, LightChoice::power, 1), 4.0 / 404.0);
  // pick_light inverts the cumulative distribution.
  EXPECT_EQ(pick_light(scene, LightChoice::uniform, 0.49), 0u);
  EXPECT_EQ(pick_light(scene, LightChoice::uniform, 0.51), 1u);
  EXPECT_EQ(pick_light(scene, LightChoice::power, 0.99), 0u);
  EXPECT_EQ(pick_light(scene, LightChoice::power, 0.995), 1u);
  // Each light's radiance from its power: Phi = 4 pi^2 r^2 Le.
  for (std::size_t j = 0; j < 2; ++j) {
    const double r = scene.lights[j].radius;
    EXPECT_NEAR(4.0 * k_pi * k_pi * r * r * scene.radiance(j), scene.power[j], 1e-9);
  }
}

// The closed form needs each light wholly above the horizon of every patch point and neither
// shadowing the other: checked on a grid of the patch, for rays towards every light's rim.
TEST(LightChoiceTest, NoLightShadowsTheOtherAndBothAreAboveEveryHorizon) {
  const TwoLights scene;
  Rng rng(5, 0);
  for (int i = 0; i <= 20; ++i)
    for (int k = 0; k <= 10; ++k) {
      const Vec3 x{-2.0 + 0.2 * i, 0.0, -1.0 + 0.2 * k};
      for (std::size_t j = 0; j < 2; ++j) {
        const Sphere& s = scene.lights[j];
        EXPECT_GT(s.center.y - s.radius, 0.0);
        for (int n = 0; n < 20; ++n) {
          const LightPoint y = sample_sphere_cone(s.center, s.radius, x, rng.uniform2());
          const Ray ray(x, glm::normalize(y.point - x));
          EXPECT_GT(ray.direction.y, 0.0);
          EXPECT_FALSE(
              intersect_distance(scene.lights[1 - j], ray, {0.0, glm::length(y.point - x)}))
              << x.x << " " << x.z << " light " << j;
        }
      }
    }
}

// n samples of the estimator at x, sample i from stream i of `seed`.
RunningStats sample_at(const TwoLights& scene, const Vec3& x, LightChoice choice, int n,
                       std::uint64_t seed, bool wrong_weight = false) {
  RunningStats s;
  RayCount count;
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, static_cast<std::uint64_t>(i));
    double y = estimate_floor_radiance(scene, x, choice, rng, count);
    // Known bug: power choice weighted as if uniform (divided by 1/N, not by P_j): biased.
    if (wrong_weight && y > 0.0) {
      const std::size_t j =
          pick_light(scene, choice, Rng(seed, static_cast<std::uint64_t>(i)).uniform());
      y *= light_choice_probability(scene, choice, j) * 2.0;
    }
    s.add(y);
  }
  EXPECT_EQ(count.rays, static_cast<std::uint64_t>(n));  // one shadow ray a sample
  return s;
}

// Points: under the bright light, the patch's corner beside the dim one (where their shares
// are 0.59 and 0.41), the centre, the far corner. z-tests of the mean against the closed form,
// Sidak-combined over the 8, at k_alpha. Power choice beside the dim light is the heavy case:
// 1 sample in 101 carries 41 % of the mean, so 10^5 samples give ~990 such, and the mean's
// skewness (~1/sqrt(990)) is far too small to move a z-test's tail.
TEST(LightChoiceTest, BothChoicesAreUnbiasedAndAWrongWeightIsCaught) {
  const TwoLights scene;
  constexpr int k_samples = 100000;
  const std::vector<Vec3> points{{-1.0, 0.0, 0.0},
                                 {1.0, 0.0, 1.0},
                                 {0.0, 0.0, 0.0},
                                 {-2.0, 0.0, -1.0}};
  std::vector<double> p_values, p_values_wrong;
  std::uint64_t seed = 11;
  for (const Vec3& x : points) {
    const double exact = exact_floor_radiance(scene, x);
    for (LightChoice choice : {LightChoice::uniform, LightChoice::power}) {
      const RunningStats s = sample_at(scene, x, choice, k_samples, seed++);
      p_values.push_back(z_test_p_value(s.mean(), exact, s.standard_error()));
    }
    const RunningStats wrong = sample_at(scene, x, LightChoice::power, k_samples, seed++, true);
    p_values_wrong.push_back(z_test_p_value(wrong.mean(), exact, wrong.standard_error()));
  }
  EXPECT_GT(sidak_p_value(p_values), k_alpha);
  EXPECT_LT(sidak_p_value(p_values_wrong), k_alpha);
}

// Var Y = sum_j C_j^2 / P_j - L^2 (the top of render/light_choice.hpp): under the bright light
// uniform choice has ~L^2, power choice ~0.006 L^2; beside the dim light uniform has ~0.03 L^2
// (the shares are close) and power ~16 L^2. Factors of 100 and 500: tested at 10, which 10^4
// samples' variance estimates (within 10 % here, 50 % for power beside the dim light, whose
// rare samples carry it) cannot miss.
TEST(LightChoiceTest, PowerWinsFarFromTheDimLightAndLosesBesideIt) {
  const TwoLights scene;
  constexpr int k_samples = 10000;
  const Vec3 under_bright{-1.0, 0.0, 0.0}, beside_dim{1.0, 0.0, 1.0};
  const double uniform_far =
      sample_at(scene, under_bright, LightChoice::uniform, k_samples, 1).variance();
  const double power_far =
      sample_at(scene, under_bright, LightChoice::power, k_samples, 2).variance();
  const double uniform_near =
      sample_at(scene, beside_dim, LightChoice::uniform, k_samples, 3).variance();
  const double power_near =
      sample_at(scene, beside_dim, LightChoice::power, k_samples, 4).variance();
  EXPECT_GT(uniform_far, 10.0 * power_far);
  EXPECT_GT(power_near, 10.0 * uniform_near);
}

}  // namespace
