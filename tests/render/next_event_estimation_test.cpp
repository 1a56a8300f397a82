// Next-event estimation (render/next_event_estimation.hpp): the furnace's exact case, the
// one-sided lamp, the point lights far from the lamp, and that the checks' procedures
// (render/next_event_estimation_procedures.hpp, scene_quad_box_reference.hpp) reject every
// known-wrong variant of tests/render/next_event_estimation_known_bugs.hpp. (The light
// samplers: tests/sampling/light_test.cpp and tests/render/light_sampling_test.cpp; MIS's
// weights: tests/render/mis_test.cpp.)
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

// Furnace, depth k <= 3 (before roulette starts): every NEE path returns exactly
// Le (1 + a + ... + a^k), the direct term a Le being exact (next_event_estimation.hpp).
TEST(NeeTest, FurnaceIsExactEverySampleBeforeRoulette) {
  const Scene furnace = make_furnace(0.5, 2.0);
  Rng dirs(5, 0);
  for (int k = 0; k <= 3; ++k)
    for (int i = 0; i < 200; ++i) {
      Rng rng(6, static_cast<std::uint64_t>(i));
      RayCount count;
      const Color l =
          estimate_nee_radiance(furnace, {Vec3(0.0), sample_uniform_sphere(dirs.uniform2())},
                                {Roulette{}, k}, rng, count);
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
  const auto lamp =
      scene.add_material(box.materials[box.quads()[box.emitters()[0].index].material()]);
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
    sum += estimate_nee_radiance(scene, {x + Vec3(0, 1, 0), Vec3(0, -1, 0)}, {Roulette{}, 1}, rng,
                                 count)
               .r;
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
  return mcrt::testing::direct_light_p_value(room, whole, mcrt::testing::direct_light_points(),
                                             20000, mcrt::testing::k_suite_seed, estimate);
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
                                                 [](double r, double h) {
                                                   return 1.0 / (k_pi * r * h);
                                                 }),
            k_alpha);
  // The cone's pdf without its 2: half the density.
  EXPECT_LT(mcrt::testing::cone_light_p_value(mcrt::testing::k_suite_seed,
                                              [](const Vec3& c, double r, const Vec3& x) {
                                                return 0.5 * sphere_cone_pdf_solid_angle(c, r, x);
                                              }),
            k_alpha);
}

}  // namespace
