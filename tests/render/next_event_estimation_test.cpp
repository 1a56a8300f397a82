// Light sampling, next-event estimation and MIS (render/light_sampling.hpp,
// render/next_event_estimation.hpp, render/mis.hpp): the samplers' geometry, the change of
// measure, MIS weights that sum to 1 for every sample, the furnace's exact case, the one-sided
// lamp, and that the checks' procedures (render/next_event_estimation_procedures.hpp, quad_box_reference.hpp)
// reject every known-wrong variant of tests/render/next_event_estimation_known_bugs.hpp.
// (The statistical checks themselves are in tests/render/next_event_estimation_checks.cpp.)

#include <gtest/gtest.h>

#include <cmath>

#include "render/next_event_estimation_known_bugs.hpp"
#include "render/light_sampling.hpp"
#include "render/mis.hpp"
#include "render/next_event_estimation.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "sampling/light.hpp"
#include "stats/check.hpp"
#include "render/next_event_estimation_procedures.hpp"
#include "render/scene_quad_box_reference.hpp"
#include "render/scene_sphere_box_reference.hpp"

using namespace mcrt;

namespace {

constexpr double k_alpha = 1e-4;  // the checks' false-failure rate

TEST(LightSamplingTest, QuadPointsLieOnTheQuadWithItsNormalAndPdf) {
  const Quad q = mcrt::testing::cornell_lamp();
  Rng rng(1, 0);
  for (int i = 0; i < 1000; ++i) {
    const LightPoint y = sample_quad(q.corner(), q.edge_u(), q.edge_v(), rng.uniform2());
    const Vec3 p = y.point - q.corner();
    EXPECT_NEAR(glm::dot(p, q.normal()), 0.0, 1e-9);
    EXPECT_GE(q.coordinate_a(p), -1e-12);
    EXPECT_LE(q.coordinate_a(p), 1.0 + 1e-12);
    EXPECT_GE(q.coordinate_b(p), -1e-12);
    EXPECT_LE(q.coordinate_b(p), 1.0 + 1e-12);
    EXPECT_NEAR(glm::length(y.normal - q.normal()), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(y.pdf_area, 1.0 / (130.0 * 105.0));
  }
}

TEST(LightSamplingTest, CapPointsLieOnTheSphereInsideTheCap) {
  const Vec3 c(50, 681.33, 81.6), axis(0, -1, 0);
  Rng rng(2, 0);
  for (int i = 0; i < 1000; ++i) {
    const LightPoint y = sample_sphere_cap(c, 600.0, axis, 0.27, rng.uniform2());
    EXPECT_NEAR(glm::length(y.point - c), 600.0, 1e-9);
    EXPECT_GE(glm::dot(y.point - c, axis), 600.0 - 0.27 - 1e-9);
    EXPECT_NEAR(glm::length(y.normal - (y.point - c) / 600.0), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(y.pdf_area, 1.0 / (k_two_pi * 600.0 * 0.27));
  }
  // The whole unit sphere: pdf 1 / (4 pi).
  EXPECT_DOUBLE_EQ(sphere_cap_pdf_area(1.0, 2.0), 0.25 * k_inv_pi);
}

TEST(LightSamplingTest, AreaAndSolidAngleConvertBothWays) {
  // p_w = p_A r^2 / |cos|, and back.
  EXPECT_DOUBLE_EQ(area_to_solid_angle_pdf(0.5, 2.0, 0.25), 0.5 * 4.0 / 0.25);
  EXPECT_DOUBLE_EQ(area_to_solid_angle_pdf(0.5, 2.0, -0.25), 8.0);
  EXPECT_DOUBLE_EQ(solid_angle_to_area_pdf(8.0, 2.0, 0.25), 0.5);
  EXPECT_EQ(area_to_solid_angle_pdf(0.5, 2.0, 0.0), 0.0);  // edge-on: no solid angle
}

TEST(MisTest, WeightsSumToOneForEveryPair) {
  Rng rng(3, 0);
  for (MisHeuristic h : {MisHeuristic::balance, MisHeuristic::power})
    for (int i = 0; i < 10000; ++i) {
      const double a = std::exp(40.0 * rng.uniform() - 20.0), b = std::exp(40.0 * rng.uniform() - 20.0);
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

// Furnace, depth k <= 3 (before roulette starts): every NEE path returns exactly
// Le (1 + a + ... + a^k), the direct term a Le being exact (next_event_estimation.hpp).
TEST(NeeTest, FurnaceIsExactEverySampleBeforeRoulette) {
  const Scene furnace = make_furnace(0.5, 2.0);
  Rng dirs(5, 0);
  for (int k = 0; k <= 3; ++k)
    for (int i = 0; i < 200; ++i) {
      Rng rng(6, static_cast<std::uint64_t>(i));
      RayCount count;
      const Color l = estimate_nee_radiance(
          furnace, {Vec3(0.0), sample_uniform_sphere(dirs.uniform2())}, {Roulette{}, k}, rng,
          count);
      // 1e-6: the shadow ray starts 1e-7 (1 + |x|) off the wall (spawn_ray), which moves
      // cos cos / r^2 by about that much.
      EXPECT_NEAR(l.r, furnace_radiance(0.5, 2.0, k), 1e-6) << "k = " << k;
    }
}

TEST(NeeTest, TheOneSidedLampLightsNothingBehindIt) {
  const auto nee = [](const Scene& s, const Ray& r, int depth, Rng& rng, RayCount& c) {
    return estimate_nee_radiance(s, r, {Roulette{}, depth}, rng, c);
  };
  const auto mis = [](const Scene& s, const Ray& r, int depth, Rng& rng, RayCount& c) {
    return estimate_mis_radiance(s, r, {Roulette{}, depth}, MisHeuristic::power, rng, c);
  };
  EXPECT_EQ(mcrt::testing::light_behind_p_value(2000, mcrt::testing::k_suite_seed, nee), 1.0);
  EXPECT_EQ(mcrt::testing::light_behind_p_value(2000, mcrt::testing::k_suite_seed, mis), 1.0);
}

// Far from a small lamp, NEE's direct light (depth 1) is chapter 01's point light with the
// area light's far field: L = (rho / pi) I(theta_l) cos(theta_x) / r^2, I(theta_l) = Le A
// cos(theta_l). The cornell lamp at scale 0.1 (13 x 10.5) seen from a floor point about 610
// away: the far field is exact to about (13 / 610)^2 = 5e-4, and 4000 NEE samples of an almost
// constant integrand give the mean to far better than the 0.3% allowed.
TEST(NeeTest, FarFromTheLampItsDirectLightIsThePointLights) {
  const Scene box = make_cornell_box(0.1);
  Scene scene;
  const auto white = scene.add_material({Color(0.73), Color(0.0)});
  const auto lamp = scene.add_material(box.materials[box.quads()[box.emitters()[0].index].material()]);
  const auto back = scene.add_material({Color(0.0), Color(0.0)});
  scene.add_quad({{-1e3, 0, -1e3}, {0, 0, 2e3}, {2e3, 0, 0}, white});
  const Quad& q = box.quads()[box.emitters()[0].index];
  scene.add_quad({q.corner(), q.edge_u(), q.edge_v(), lamp}, back);
  const Vec3 x(100, 0, 100);
  double sum = 0.0;
  constexpr int n = 4000;
  for (int i = 0; i < n; ++i) {
    Rng rng(7, static_cast<std::uint64_t>(i));
    RayCount count;
    sum += estimate_nee_radiance(scene, {x + Vec3(0, 1, 0), Vec3(0, -1, 0)}, {Roulette{}, 1},
                                 rng, count).r;
  }
  const PointLight& light = box.point_light;
  const Vec3 to_light = light.position - x;
  const double r = glm::length(to_light);
  const Vec3 wi = to_light / r;
  const double expected = 0.73 * k_inv_pi * light.intensity_towards(-wi).r * wi.y / (r * r);
  EXPECT_NEAR(sum / n / expected, 1.0, 3e-3);
}

// The checks' direct-light procedure (render/next_event_estimation_checks.cpp: four floor points, 20000 paths each).
double direct_light_p(const auto& estimate) {
  const Scene whole = make_cornell_box();
  const Scene room = mcrt::testing::cornell_room_without_boxes();
  return mcrt::testing::direct_light_p_value(room, whole, mcrt::testing::direct_light_points(), 20000,
                                       mcrt::testing::k_suite_seed, estimate);
}

TEST(NeeKnownBugsTest, JacobianLeftOutIsRejected) {
  EXPECT_LT(direct_light_p(mcrt::testing::nee_without_jacobian), k_alpha);
}
TEST(NeeKnownBugsTest, EmissionCountedTwiceIsRejected) {
  EXPECT_LT(direct_light_p(mcrt::testing::nee_emission_twice), k_alpha);
}
TEST(NeeKnownBugsTest, ShadowRayBlockedByTheLightIsRejected) {
  EXPECT_LT(direct_light_p(mcrt::testing::nee_shadow_ray_hits_light), k_alpha);
}
TEST(NeeKnownBugsTest, MisWeightsNotSummingToOneAreRejected) {
  EXPECT_LT(direct_light_p(mcrt::testing::mis_weights_not_summing_to_one), k_alpha);
}
TEST(NeeKnownBugsTest, OneSidedLightSampledFromBehindIsRejected) {
  EXPECT_LT(mcrt::testing::light_behind_p_value(2000, mcrt::testing::k_suite_seed,
                                          mcrt::testing::nee_light_from_behind),
            k_alpha);
}
// Where light sampling aims on a sphere light (light_sampling.hpp): the cap from inside the
// enclosure (the room), the cone of the whole sphere from outside both (above the ceiling),
// the whole sphere from inside it (the furnace).
TEST(LightSamplingTest, SphereLightPartFollowsTheShadingPoint) {
  const Scene spheres = make_cornell_spheres();
  const Emitter& e = spheres.emitters()[0];
  const Sphere& light = spheres.spheres()[e.index];
  EXPECT_EQ(sphere_light_part(light, e, Vec3(50, 40, 80)), SphereLightPart::cap);
  EXPECT_EQ(sphere_light_part(light, e, Vec3(50, 81.5, 80)), SphereLightPart::cap);
  EXPECT_EQ(sphere_light_part(light, e, mcrt::testing::k_above_ceiling), SphereLightPart::cone);
  const Scene furnace = make_furnace(0.5, 1.0);
  EXPECT_EQ(sphere_light_part(furnace.spheres()[0], furnace.emitters()[0], Vec3(0.3, 0, 0)),
            SphereLightPart::whole);
  EXPECT_EQ(sphere_light_part(furnace.spheres()[0], furnace.emitters()[0], Vec3(0, 3, 0)),
            SphereLightPart::cone);
}

// The cone sampler's points lie on the sphere's near side, within the cone, and their area
// pdf is p_w cos(theta_y) / r^2 with p_w = 1 / (2 pi (1 - cos(theta_max))).
TEST(LightSamplingTest, ConePointsLieOnTheNearSideWithTheConePdf) {
  const Sphere light = mcrt::testing::cornell_spheres_light();
  const Vec3 x = mcrt::testing::k_above_ceiling;
  const double d = glm::length(light.center - x);
  const double cos_max = std::sqrt(1.0 - light.radius * light.radius / (d * d));
  const double p_w = 1.0 / (k_two_pi * (1.0 - cos_max));
  EXPECT_NEAR(sphere_cone_pdf_solid_angle(light.center, light.radius, x), p_w, 1e-12 * p_w);
  Rng rng(4, 0);
  for (int i = 0; i < 1000; ++i) {
    const LightPoint y = sample_sphere_cone(light.center, light.radius, x, rng.uniform2());
    const Vec3 to_y = y.point - x;
    const double r = glm::length(to_y);
    EXPECT_NEAR(glm::length(y.point - light.center), light.radius, 1e-9);
    EXPECT_GE(glm::dot(to_y / r, glm::normalize(light.center - x)), cos_max - 1e-9);
    const double cos_y = -glm::dot(y.normal, to_y / r);
    EXPECT_GE(cos_y, -1e-9) << "a point of the far side";
    EXPECT_NEAR(y.pdf_area, p_w * cos_y / (r * r), 1e-6 * y.pdf_area);
  }
}

// Cap-only light sampling gives the wall above the ceiling no direct light.
TEST(NeeKnownBugsTest, CapOnlySphereLightIsRejectedAboveTheCeiling) {
  EXPECT_LT(mcrt::testing::above_ceiling_direct_light_p_value(
                20000, mcrt::testing::k_suite_seed, mcrt::testing::nee_cap_only,
                [](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
                  return estimate_path_radiance(s, ray, depth, rng, count);
                }),
            k_alpha);
}

TEST(NeeKnownBugsTest, WrongAreaPdfsAreRejectedByTheChiSquare) {
  // Half the true density: the expected counts no longer match.
  EXPECT_LT(mcrt::testing::quad_light_pdf_p_value(mcrt::testing::k_suite_seed,
                                            [](double area) { return 0.5 / area; }),
            k_alpha);
  EXPECT_LT(mcrt::testing::cap_light_pdf_p_value(mcrt::testing::k_suite_seed,
                                           [](double r, double h) { return 1.0 / (k_pi * r * h); }),
            k_alpha);
  // The cone's pdf without its 2: half the density.
  EXPECT_LT(mcrt::testing::cone_light_p_value(mcrt::testing::k_suite_seed,
                                              [](const Vec3& c, double r, const Vec3& x) {
                                                return 0.5 * sphere_cone_pdf_solid_angle(c, r, x);
                                              }),
            k_alpha);
}

}  // namespace
