// MIS weights (render/mis.hpp): the balance and power heuristics' weights of two strategies
// sum to 1 for every pair of pdfs, and for every light sample of the Cornell box with the pdfs
// the path tracer computes for the same direction.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/rng.hpp"
#include "render/light_sampling.hpp"
#include "render/mis.hpp"
#include "render/scene.hpp"
#include "sampling/hemisphere.hpp"

using namespace mcrt;

namespace {

TEST(MisTest, WeightsSumToOneForEveryPair) {
  Rng rng(3, 0);
  for (MisHeuristic h : {MisHeuristic::balance, MisHeuristic::power})
    for (int i = 0; i < 10000; ++i) {
      const double a = std::exp(40.0 * rng.uniform() - 20.0),
                   b = std::exp(40.0 * rng.uniform() - 20.0);
      EXPECT_NEAR(mis_weight(h, a, b) + mis_weight(h, b, a), 1.0, 1e-12);
      EXPECT_GE(mis_weight(h, a, b), 0.0);
    }
  EXPECT_EQ(mis_weight(MisHeuristic::balance, 0.0, 0.0), 0.0);
  EXPECT_EQ(mis_weight(MisHeuristic::power, 2.0, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(mis_weight(MisHeuristic::balance, 1.0, 3.0), 0.25);
  EXPECT_DOUBLE_EQ(mis_weight(MisHeuristic::power, 1.0, 3.0), 0.1);
}

// For light samples drawn from floor points of cornell: the light strategy's weight with the
// pdfs of that direction, plus the BSDF strategy's weight of the same direction, is 1; and the
// pdf light_pdf_towards gives a BSDF ray reaching the lamp is the one light sampling used.
TEST(MisTest, WeightsOfBothStrategiesSumToOneForEverySampleInTheScene) {
  const Scene scene = make_cornell_box();
  Rng rng(4, 0);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    Hit hit;
    hit.point = Vec3(50 + 450 * rng.uniform(), 0.0, 50 + 450 * rng.uniform());
    hit.normal = Vec3(0, 1, 0);
    RayCount count;
    const DirectSample d = sample_direct_light(scene, hit, rng, count);
    if (!d.contributes()) continue;
    const double p_b = cosine_hemisphere_pdf(d.cos_x);
    const Ray ray = spawn_ray(hit, d.wi);
    const std::optional<Hit> lamp = scene.closest_hit(ray);
    ASSERT_TRUE(lamp);
    const double p_l = light_pdf_towards(scene, ray, *lamp);
    EXPECT_NEAR(p_l / d.pdf_light, 1.0, 1e-6);
    for (MisHeuristic h : {MisHeuristic::balance, MisHeuristic::power})
      EXPECT_NEAR(mis_weight(h, d.pdf_light, p_b) + mis_weight(h, p_b, p_l), 1.0, 1e-6);
    ++checked;
  }
  EXPECT_GT(checked, 500);  // fixed seed: 944 floor points see the lamp
}

}  // namespace
