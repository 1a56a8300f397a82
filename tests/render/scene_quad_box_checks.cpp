// The quad Cornell box (`cornell`, render/scene.cpp make_cornell_box) against an independent
// reference (render/scene_quad_box_reference.hpp):
//  - the project's path tracer, through the project's render loop, agrees block by block and
//    in every channel with a renderer written from scratch in the test tree (its own scene
//    statement, triangles by Moller-Trumbore, cosine sampling, Russian roulette, box filter);
//  - the direct light of the area lamp on the floor agrees with Lambert's closed form for a
//    polygon light's irradiance.
// Both are designed for a false-failure rate alpha = 1e-4 (Sidak over blocks / points).

#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "stats/check.hpp"
#include "render/scene_quad_box_reference.hpp"

namespace {

using namespace mcrt;

// The project cuts paths at depth 50, the reference does not cut. The light a cut misses is
// sum over j > 50 of (T^j Le), T the transport operator, whose sup-norm is at most the largest
// albedo (0.73; the integral of cos / pi over the hemisphere is 1): at most
// 15 x 0.73^51 / (1 - 0.73) = 6e-6 in any channel of any pixel. A block's standard error is
// about 1e-2 (16 pixels x 2000 samples per renderer), so the bias moves the statistic by
// under 1e-3 standard errors: nothing a test at alpha = 1e-4 can see.
// 16 x 12 pixels, 4 x 4 blocks (12 blocks x 3 channels), 2000 samples per pixel each: 1.5 s.
MCRT_STATISTICAL_CHECK_AT_MOST(path_tracer_agrees_with_independent_renderer_cornell, 1e-4) {
  const Scene scene = make_cornell_box();
  return mcrt::testing::quad_box_comparison_p_value(
      scene, {}, seed, [](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
        return estimate_path_radiance(s, ray, depth, rng, count);
      });
}

// Four floor points (render/scene_quad_box_reference.hpp direct_light_points), 2e5 paths each: the
// lamp covers about 0.7% of the hemisphere above the centre point, so about 1400 paths reach
// it and the relative standard error is about 3%.
MCRT_STATISTICAL_CHECK(cornell_lamp_direct_light_matches_lambert_formula, 1e-4) {
  const Scene whole = make_cornell_box();
  const Scene room = mcrt::testing::cornell_room_without_boxes();
  return mcrt::testing::direct_light_p_value(
      room, whole, mcrt::testing::direct_light_points(), 200000, seed,
      [](const Scene& s, const Ray& ray, int depth, Rng& rng, RayCount& count) {
        return estimate_path_radiance(s, ray, depth, rng, count);
      });
}

}  // namespace
