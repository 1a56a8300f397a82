// The independent reference for the quad Cornell box (render/scene_quad_box_reference.hpp): its
// closed form against a second closed form, its scene statement against `cornell` ray by ray,
// and the procedures of tests/render/scene_quad_box_checks.cpp rejecting known-wrong tracers.

#include <gtest/gtest.h>

#include <cmath>

#include "render/path_tracer_known_bugs.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "render/scene_quad_box_reference.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

TEST(QuadBoxReferenceTest, LambertFormulaMatchesTheParallelRectangleFormFactor) {
  // Under a corner of an a x b rectangle at height c, E = pi Le F; under an inner point, the
  // sum of the four rectangles that point cuts it into.
  const double a = 130.0, b = 105.0, c = 554.0, le = 15.0;
  const std::array<Vec3, 4> lamp{Vec3(0, c, 0), Vec3(a, c, 0), Vec3(a, c, b), Vec3(0, c, b)};
  const Vec3 up(0, 1, 0);
  // 1e-12 relative: a few roundings of acos and atan of unit-size values.
  EXPECT_NEAR(polygon_irradiance(Vec3(0.0), up, lamp, le),
              k_pi * le * corner_rectangle_form_factor(a, b, c), 1e-12 * le);
  const double x = 40.0, z = 70.0;
  const double parts =
      corner_rectangle_form_factor(x, z, c) + corner_rectangle_form_factor(a - x, z, c) +
      corner_rectangle_form_factor(x, b - z, c) + corner_rectangle_form_factor(a - x, b - z, c);
  EXPECT_NEAR(polygon_irradiance(Vec3(x, 0, z), up, lamp, le), k_pi * le * parts, 1e-12 * le);
  // Far away the lamp is a point source: E -> Le A cos / r^2.
  const double r = 1e5 + c;
  EXPECT_NEAR(polygon_irradiance(Vec3(65, -1e5, 52.5), up, lamp, le) * r * r, le * a * b,
              1e-3 * le * a * b);
}

TEST(QuadBoxReferenceTest, MollerTrumboreHitsInsideAndMissesOutside) {
  const ReferenceTriangle tri{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Color(1), Color(0)};
  const Vec3 down(0, 0, -1);
  EXPECT_NEAR(*moller_trumbore(tri, Vec3(0.2, 0.2, 3), down, 1e-6), 3.0, 1e-15);
  EXPECT_NEAR(*moller_trumbore(tri, Vec3(0.2, 0.2, -3), -down, 1e-6), 3.0, 1e-15);
  EXPECT_FALSE(moller_trumbore(tri, Vec3(0.6, 0.6, 3), down, 1e-6));   // beyond the hypotenuse
  EXPECT_FALSE(moller_trumbore(tri, Vec3(-0.1, 0.2, 3), down, 1e-6));  // left of the corner
  EXPECT_FALSE(moller_trumbore(tri, Vec3(0.2, 0.2, 3), -down, 1e-6));  // behind the ray
  EXPECT_FALSE(moller_trumbore(tri, Vec3(0.2, 0.2, 1), Vec3(1, 0, 0), 1e-6));  // parallel
}

// The reference's own statement of the scene against make_cornell_box: along camera rays and
// random rays from inside the box, the same first surface at the same distance with the same
// albedo and emission. (This is where a wrong wall, lamp or box turn shows at once; the image
// check then compares the light.)
TEST(QuadBoxReferenceTest, SceneStatementMatchesCornellRayByRay) {
  const Scene scene = make_cornell_box();
  const ReferenceQuadBox box = make_reference_quad_box();
  const Camera camera(scene.camera, 64, 48);
  Rng rng(5, 0);
  int compared = 0;
  auto compare = [&](const Vec3& o, const Vec3& d) {
    const std::optional<Hit> ours = scene.closest_hit({o, d});
    const std::optional<ReferenceHit> theirs = reference_closest_hit(box, o, d);
    ASSERT_EQ(ours.has_value(), theirs.has_value()) << o.x << "," << o.y << "," << o.z;
    if (!ours) return;
    ++compared;
    // 1e-9 relative: distances below 2e3 computed two ways in double.
    EXPECT_NEAR(ours->t, theirs->t, 1e-9 * ours->t);
    const ReferenceTriangle& tri = box.triangles[theirs->triangle];
    EXPECT_EQ(scene.material(*ours).albedo, tri.albedo);
    EXPECT_EQ(scene.material(*ours).emission, tri.emission);
  };
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const Vec2 u = rng.uniform2();
      const Ray ray = camera.generate_ray(x, y, u);
      EXPECT_LT(glm::length(ray.direction -
                            reference_camera_direction(box, 64, 48, x + u.x, y + u.y)),
                1e-12);
      compare(ray.origin, ray.direction);
    }
  for (int i = 0; i < 20000; ++i) {
    const Vec3 o = 555.0 * Vec3(rng.uniform(), rng.uniform(), rng.uniform());
    const double z = 2.0 * rng.uniform() - 1.0, phi = k_two_pi * rng.uniform();
    const double r = std::sqrt(1.0 - z * z);
    compare(o, Vec3(r * std::cos(phi), r * std::sin(phi), z));
  }
  EXPECT_GT(compared, 15000);  // rays that leave by the open front are not compared
}

TEST(QuadBoxReferenceTest, TheFullBoxPointSeesTheWholeLamp) {
  // The closed form needs the whole lamp in view: rays to a 21 x 21 grid over it reach it
  // (the grid's cell centres: a ray aimed exactly at the lamp's rim may miss it by round-off).
  const ReferenceQuadBox box = make_reference_quad_box();
  for (const FloorPoint& p : direct_light_points()) {
    if (!p.whole_box) continue;
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const Vec3 target = box.lamp[0] + ((i + 0.5) / 21.0) * (box.lamp[1] - box.lamp[0]) +
                            ((j + 0.5) / 21.0) * (box.lamp[3] - box.lamp[0]);
        const Vec3 d = glm::normalize(target - p.x);
        const std::optional<ReferenceHit> hit = reference_closest_hit(box, p.x, d);
        ASSERT_TRUE(hit);
        EXPECT_EQ(box.triangles[hit->triangle].emission, box.lamp_radiance) << i << "," << j;
      }
  }
}

TEST(QuadBoxReferenceTest, CosineDirectionsLieAroundTheNormal) {
  // A ray straight up from the floor of the room: the reference's bounce directions must stay
  // above the floor, so paths from a floor point never see below it. Checked through the
  // estimate: with the lamp the only emitter, every sample is 0 or a positive multiple of Le.
  const ReferenceQuadBox box = make_reference_quad_box();
  for (std::uint64_t s = 0; s < 2000; ++s) {
    Rng rng(3, s);
    const Color l = reference_radiance(box, Vec3(278, 100, 279.5), Vec3(0, -1, 0), rng);
    EXPECT_TRUE(is_finite(l));
    EXPECT_GE(std::min({l.x, l.y, l.z}), 0.0);
  }
}

TEST(QuadBoxReferenceTest, ProceduresRejectKnownWrongTracers) {
  const Scene whole = make_cornell_box();
  const Scene room = cornell_room_without_boxes();
  // The check runs at alpha = 1e-4 with 2e5 paths per point; these rejections come with 2e4.
  EXPECT_LT(direct_light_p_value(room, whole, direct_light_points(), 20000, 7,
                                 path_radiance_without_cosine),
            1e-4);
  EXPECT_LT(direct_light_p_value(room, whole, direct_light_points(), 20000, 7,
                                 path_radiance_with_sphere_pdf),
            1e-4);
  // The image comparison sees a path cut after 1 bounce (no indirect light at all). (A cut at
  // 2 bounces gives p of about 1e-3 at the check's size: its power is for gross errors.)
  QuadBoxComparison cut;
  cut.depth = 1;
  EXPECT_LT(quad_box_comparison_p_value(whole, cut, 7,
                                        [](const Scene& s, const Ray& ray, int depth, Rng& rng,
                                           RayCount& count) {
                                          return estimate_path_radiance(s, ray, depth, rng, count);
                                        }),
            1e-4);
}

}  // namespace
