// Light sampling, next-event estimation and MIS (render/light_sampling.hpp,
// render/next_event_estimation.hpp, render/mis.hpp) against closed forms and against chapter
// 07's estimator:
//  - the light samplers' pdfs per unit area: chi-square (the quad lamp of cornell, the light cap
//    of cornell-spheres); the change to solid angle: the light pdf per steradian integrates to
//    1 over the light, a z-test (the samplers work in area measure; solid angle is used only as
//    this conversion, for the shadow ray's weight and the MIS weights);
//  - the direct light on cornell's floor (depth 1) equals Lambert's polygon formula
//    (render/scene_quad_box_reference.hpp), for NEE and for MIS with either heuristic;
//  - the furnace with Russian roulette: the mean is Le / (1 - a) (z-test);
//  - NEE and MIS agree by blocks, rows, columns and the image border with the independent
//    renderers of the quad box (render/scene_quad_box_reference.hpp, which chapter 05's path tracer
//    is checked against too) and of smallpt's sphere box (render/scene_sphere_box_reference.hpp),
//    whose top rows start above the ceiling and see the light beyond its cap;
//  - from such a point, above the ceiling, the light pdf per steradian integrates to 1 too;
//  - NEE and MIS agree with chapter 07's cosine estimator block by block on a small cornell
//    image, at light scales 1 and 3 (z-tests of block means, Sidak). Not at small light
//    scales: there the cosine estimator's rare hits on a bright lamp make its block means too
//    skewed for the normal approximation at these sample counts. Measured at light scale 0.3
//    (NEE against cosine, 8 seeds each): 7 of 8 rejected at 1e-4 with 600 samples per pixel,
//    1 of 8 with 6000, none with 30000. A bias would be rejected more often as the samples
//    grow; this falls, as the skew of a mean of rare hits does. The calibration run also found
//    cosine against cosine and NEE against MIS consistent at that scale (no rejection at 1e-4
//    in 200 seeds each).
// Every check is designed for a false-failure rate alpha = 1e-4.

#include <cmath>

#include "integration/statistics.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/mis.hpp"
#include "render/path_tracer.hpp"
#include "render/next_event_estimation.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "sampling/light.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"
#include "render/next_event_estimation_procedures.hpp"
#include "render/scene_quad_box_reference.hpp"
#include "render/scene_sphere_box_reference.hpp"

namespace {

using namespace mcrt;

MCRT_STATISTICAL_CHECK(quad_light_pdf_per_area_chi_square, 1e-4) {
  return mcrt::testing::quad_light_pdf_p_value(seed, quad_pdf_area);
}

MCRT_STATISTICAL_CHECK(sphere_cap_light_pdf_per_area_chi_square, 1e-4) {
  return mcrt::testing::cap_light_pdf_p_value(seed, sphere_cap_pdf_area);
}

// The lamp alone, seen from 200 below its centre, then the light cap alone from 40 below it:
// 1e5 directions each, about 1% and 10% of them reach the light.
MCRT_STATISTICAL_CHECK(quad_light_pdf_per_steradian_integrates_to_one, 1e-4) {
  Scene scene;
  const auto light = scene.add_material({Color(0.0), Color(15.0)});
  const auto back = scene.add_material({Color(0.0), Color(0.0)});
  const Quad lamp = mcrt::testing::cornell_lamp();
  scene.add_quad({lamp.corner(), lamp.edge_u(), lamp.edge_v(), light}, back);
  return mcrt::testing::light_pdf_normalisation_p_value(scene, Vec3(278, 354, 279.5), Vec3(0, 1, 0),
                                                        100000, seed, 50);
}

// The cap from inside the room: the light and the ceiling that hides all of it but the cap.
MCRT_STATISTICAL_CHECK(sphere_cap_light_pdf_per_steradian_integrates_to_one, 1e-4) {
  Scene scene;
  const auto light = scene.add_material({Color(0.0), Color(12.0)});
  scene.add_sphere({{50, -1e5 + 81.6, 81.6}, 1e5, scene.add_material({Color(0.75), Color(0.0)})});
  scene.add_sphere_light({{50, 681.6 - 0.27, 81.6}, 600, light}, 0);
  return mcrt::testing::light_pdf_normalisation_p_value(scene, Vec3(50, 41.6, 81.6), Vec3(0, 1, 0),
                                                        100000, seed, 51);
}

// The cone sampler (sphere lights seen from outside): from a point between cornell-spheres'
// ceiling and its light, above the ceiling plane, where the top rows' camera rays meet the
// left wall. Its directions' (cos theta, phi) about the axis to the centre, chi-square against
// the uniform density; and, the light alone, p_w integrates to 1 over uniform directions of
// the hemisphere around that axis (the cone, 83 degrees wide, lies inside it). About 94% of
// the 1e5 directions reach the light.
MCRT_STATISTICAL_CHECK(sphere_cone_light_chi_square, 1e-4) {
  return mcrt::testing::cone_light_p_value(seed, sphere_cone_pdf_solid_angle);
}

MCRT_STATISTICAL_CHECK(sphere_cone_light_pdf_per_steradian_integrates_to_one, 1e-4) {
  const Sphere light = mcrt::testing::cornell_spheres_light();
  const Vec3 x = mcrt::testing::k_above_ceiling;
  Scene scene;
  scene.add_sphere({light.center, light.radius, scene.add_material({Color(0.0), Color(12.0)})});
  return mcrt::testing::light_pdf_normalisation_p_value(scene, x, glm::normalize(light.center - x),
                                                        100000, seed, 52);
}

// Above cornell-spheres' ceiling (render/next_event_estimation_procedures.hpp): 20000 rays per strip each.
double above_ceiling_check(std::uint64_t seed, bool mis) {
  return mcrt::testing::above_ceiling_direct_light_p_value(
      20000, seed,
      [mis](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
        const PathEnd end{Roulette{}, depth};
        return mis ? estimate_mis_radiance(s, ray, end, MisHeuristic::power, rng, count)
                   : estimate_nee_radiance(s, ray, end, rng, count);
      },
      [](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
        return estimate_path_radiance(s, ray, depth, rng, count);
      });
}
MCRT_STATISTICAL_CHECK(nee_direct_light_above_ceiling_matches_path_tracer, 1e-4) {
  return above_ceiling_check(seed, false);
}
MCRT_STATISTICAL_CHECK(mis_direct_light_above_ceiling_matches_path_tracer, 1e-4) {
  return above_ceiling_check(seed, true);
}

// Direct light at four floor points (quad_box_reference.hpp), 20000 paths each at depth 1.
double direct_light_check(std::uint64_t seed, const auto& estimate) {
  const Scene whole = make_cornell_box();
  const Scene room = mcrt::testing::cornell_room_without_boxes();
  return mcrt::testing::direct_light_p_value(room, whole, mcrt::testing::direct_light_points(),
                                             20000, seed, estimate);
}

MCRT_STATISTICAL_CHECK(nee_direct_light_matches_lambert_formula, 1e-4) {
  return direct_light_check(seed, [](const Scene& s, const Ray& ray, int depth, Rng& rng,
                                     RayCount& count) {
    return estimate_nee_radiance(s, ray, {Roulette{}, depth}, rng, count);
  });
}

MCRT_STATISTICAL_CHECK(mis_power_direct_light_matches_lambert_formula, 1e-4) {
  return direct_light_check(seed, [](const Scene& s, const Ray& ray, int depth, Rng& rng,
                                     RayCount& count) {
    return estimate_mis_radiance(s, ray, {Roulette{}, depth}, MisHeuristic::power, rng, count);
  });
}

MCRT_STATISTICAL_CHECK(mis_balance_direct_light_matches_lambert_formula, 1e-4) {
  return direct_light_check(seed, [](const Scene& s, const Ray& ray, int depth, Rng& rng,
                                     RayCount& count) {
    return estimate_mis_radiance(s, ray, {Roulette{}, depth}, MisHeuristic::balance, rng, count);
  });
}

// The furnace (a = 0.5, Le = 1) from its centre with roulette and no cut: mean Le / (1 - a) = 2.
// 40000 paths; the variance comes from roulette alone.
double furnace_roulette_check(std::uint64_t seed, std::uint64_t block, bool mis) {
  const Scene furnace = make_furnace(0.5, 1.0);
  const PathEnd end{Roulette{}, -1};
  const std::vector<FurnacePath> paths =
      trace_furnace_paths(40000, seed, 60 + block, 1, [&](const Ray& ray, Rng& rng, RayCount& c) {
        return mis ? estimate_mis_radiance(furnace, ray, end, MisHeuristic::power, rng, c)
                   : estimate_nee_radiance(furnace, ray, end, rng, c);
      });
  RunningStats stats;
  for (const FurnacePath& p : paths) stats.add(p.radiance);
  return mcrt::testing::z_test_p_value(stats.mean(), furnace_radiance_untruncated(0.5, 1.0),
                                       stats.standard_error());
}

MCRT_STATISTICAL_CHECK(nee_furnace_mean_with_roulette, 1e-4) {
  return furnace_roulette_check(seed, 0, false);
}
MCRT_STATISTICAL_CHECK(mis_furnace_mean_with_roulette, 1e-4) {
  return furnace_roulette_check(seed, 1, true);
}

// 12 x 9 pixels, 3 x 3 blocks (12 blocks x 3 channels), 6000 samples per pixel per estimator,
// depth 4: chapter 07's cosine estimator against NEE and against MIS (power). The cosine
// estimator finds the small lamp rarely, so its block means are skewed: at 600 samples correct
// code was rejected at 26 of 300 seeds at 1e-4 (89 at 0.05), at 6000 at none of 300 (18 at
// 0.05, 6 at 0.01). More samples removed the rejections: the signature of skew, not of bias,
// which they would expose. The Sidak combination over correlated channels does not give
// uniform p-values (two-sided KS p 5e-11 over those 300 seeds), so the check is declared "at
// most alpha" and calibrated one-sided: no rate significantly above its level.
double agreement_check(std::uint64_t seed, double light_scale, bool mis) {
  SceneParams params;
  params.light_scale = light_scale;
  const Scene scene = make_scene("cornell", params);
  constexpr int k_depth = 4;
  const PathEnd end{Roulette{}, k_depth};
  return mcrt::testing::block_agreement_p_value(
      scene, 12, 9, 3, 6000, seed,
      [&](const Ray& ray, Rng& rng, RayCount& count) {
        return estimate_importance_path_radiance(scene, ray, k_depth, cosine_power_pdf(1), rng,
                                                 count);
      },
      [&](const Ray& ray, Rng& rng, RayCount& count) {
        return mis ? estimate_mis_radiance(scene, ray, end, MisHeuristic::power, rng, count)
                   : estimate_nee_radiance(scene, ray, end, rng, count);
      });
}

MCRT_STATISTICAL_CHECK_AT_MOST(nee_agrees_with_cosine_estimator_by_block, 1e-4) {
  return agreement_check(seed, 1.0, false);
}
MCRT_STATISTICAL_CHECK_AT_MOST(mis_agrees_with_cosine_estimator_by_block, 1e-4) {
  return agreement_check(seed, 1.0, true);
}
MCRT_STATISTICAL_CHECK_AT_MOST(nee_agrees_with_cosine_estimator_by_block_large_light, 1e-4) {
  return agreement_check(seed, 3.0, false);
}

// NEE and MIS against the renderers written from scratch in the test tree (their own scene
// statements and intersections, cosine sampling, Russian roulette), by blocks, rows, columns
// and border. The quad box: the same image and samples as the path tracer's check in
// render/scene_quad_box_checks.cpp, against the test tree's own NEE (reference_radiance_nee: against the
// path-traced reference, whose rare lamp hits skew its region means, the rows and border
// rejected correct code at 12 % of seeds at 0.05), with paths ended by roulette and cut at
// depth 50 (a bias below 6e-6 there, far below a block's standard error of about 1e-2).
MCRT_STATISTICAL_CHECK_AT_MOST(nee_agrees_with_independent_renderer_cornell, 1e-4) {
  return mcrt::testing::quad_box_comparison_p_value(
      make_cornell_box(), {.nee_reference = true}, seed,
      [](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
        return estimate_nee_radiance(s, ray, PathEnd{Roulette{}, depth}, rng, count);
      });
}
MCRT_STATISTICAL_CHECK_AT_MOST(mis_agrees_with_independent_renderer_cornell, 1e-4) {
  return mcrt::testing::quad_box_comparison_p_value(
      make_cornell_box(), {.nee_reference = true}, seed,
      [](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
        return estimate_mis_radiance(s, ray, PathEnd{Roulette{}, depth}, MisHeuristic::power, rng,
                                     count);
      });
}

// smallpt's sphere box, 32 x 24 pixels, 2000 samples per pixel each, paths ended by roulette
// alone (unbiased for every bounce, like the reference), compared row by row (the top row
// included), column by column, block by block and on the border.
double sphere_box_check(std::uint64_t seed, bool mis) {
  return mcrt::testing::sphere_box_comparison(
             make_cornell_spheres(), {32, 24, 4, 2000}, seed,
             [mis](const Scene& s, const Ray& ray, Rng& rng, RayCount& count) {
               const PathEnd end{Roulette{}, -1};
               return mis ? estimate_mis_radiance(s, ray, end, MisHeuristic::power, rng, count)
                          : estimate_nee_radiance(s, ray, end, rng, count);
             })
      .p_value;
}
MCRT_STATISTICAL_CHECK_AT_MOST(nee_agrees_with_independent_renderer_cornell_spheres, 1e-4) {
  return sphere_box_check(seed, false);
}
MCRT_STATISTICAL_CHECK_AT_MOST(mis_agrees_with_independent_renderer_cornell_spheres, 1e-4) {
  return sphere_box_check(seed, true);
}

}  // namespace
