// The built-in scenes and the closest-hit / any-hit queries.

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "render/scene.hpp"
#include "sampling/light.hpp"
#include "sampling/sampling.hpp"

using namespace mcrt;

namespace {

TEST(SceneTest, EveryNamedSceneBuilds) {
  for (const std::string& name : scene_names()) {
    const Scene scene = make_scene(name);
    EXPECT_EQ(scene.name, name);
    EXPECT_FALSE(scene.materials.empty());
    EXPECT_FALSE(scene.spheres().empty() && scene.quads().empty());
  }
  EXPECT_THROW(make_scene("no-such-scene"), std::invalid_argument);
}

TEST(SceneTest, CornellSpheresIsSmallptsSceneAllDiffuse) {
  const Scene scene = make_cornell_spheres();
  ASSERT_EQ(scene.spheres().size(), 9u);
  const Sphere& light = scene.spheres()[8];
  EXPECT_EQ(light.radius, 600.0);
  EXPECT_EQ(scene.materials[light.material].emission, Color(12.0));
  EXPECT_EQ(scene.materials[scene.spheres()[6].material].albedo, Color(0.999));
  EXPECT_EQ(scene.materials[scene.spheres()[0].material].albedo, Color(.75, .25, .25));
  int emitters = 0;
  for (const Material& m : scene.materials) emitters += m.is_emitter();
  EXPECT_EQ(emitters, 1);
}

TEST(SceneTest, CornellBoxIsRedLeftGreenRightWithALightAbove) {
  const Scene scene = make_cornell_box();
  const Camera camera(scene.camera, 100, 100);
  const auto albedo_at = [&](double px, double py) {
    const auto hit = scene.closest_hit(camera.generate_ray(px, py));
    EXPECT_TRUE(hit);
    return hit ? scene.material(*hit).albedo : Color(-1.0);
  };
  const Color left = albedo_at(5, 50), right = albedo_at(95, 50);
  EXPECT_GT(left.r, left.g);    // red wall on the left
  EXPECT_GT(right.g, right.r);  // green wall on the right
  // Straight up from the middle of the floor: the light.
  const auto up = scene.closest_hit({{278, 1, 278}, {0, 1, 0}});
  ASSERT_TRUE(up);
  EXPECT_TRUE(scene.material(*up).is_emitter());
}

TEST(SceneTest, ClosestHitIsTheNearestOfAllPrimitives) {
  // Brute force over every primitive, for many random rays from inside the sphere box.
  const Scene scene = make_cornell_spheres();
  Rng rng(1, 0);
  for (int i = 0; i < 2000; ++i) {
    const Vec3 origin(10 + 80 * rng.uniform(), 5 + 70 * rng.uniform(), 10 + 150 * rng.uniform());
    const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
    const Ray ray{origin, rng.uniform() < 0.5 ? local : -local};
    double nearest = 1e300;
    for (const Sphere& s : scene.spheres())
      if (const auto t = intersect_distance(s, ray, {})) nearest = std::min(nearest, *t);
    const auto hit = scene.closest_hit(ray);
    if (nearest == 1e300) {
      EXPECT_FALSE(hit);
    } else {
      ASSERT_TRUE(hit);
      EXPECT_EQ(hit->t, nearest);
      EXPECT_TRUE(scene.any_hit(ray));
      EXPECT_FALSE(scene.any_hit(ray, {1e-9, nearest * (1 - 1e-9)}));
    }
  }
}

TEST(SceneTest, FurnaceEnclosesTheCamera) {
  const Scene scene = make_furnace(0.3, 2.0);
  EXPECT_EQ(scene.materials[0].albedo, Color(0.3));
  EXPECT_EQ(scene.materials[0].emission, Color(2.0));
  Rng rng(2, 0);
  for (int i = 0; i < 100; ++i) {
    const Vec3 d = sample_uniform_hemisphere(rng.uniform2());
    const auto hit = scene.closest_hit({Vec3(0.0), rng.uniform() < 0.5 ? d : -d});
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.0, 1e-12);
  }
}

TEST(SceneTest, PointLightIsTheAreaLightsFarField) {
  // I(theta) = Le A cos(theta) about the lamp's normal (down), 0 above it.
  const Scene box = make_cornell_box();
  const Color down = box.point_light.intensity_towards(Vec3(0, -1, 0));
  EXPECT_NEAR(down.r, 15.0 * 130.0 * 105.0, 1e-9);
  const Vec3 slanted = glm::normalize(Vec3(1, -1, 0));
  EXPECT_NEAR(box.point_light.intensity_towards(slanted).r, 15.0 * 130.0 * 105.0 / std::sqrt(2.0),
              1e-6);
  EXPECT_EQ(box.point_light.intensity_towards(Vec3(0, 1, 0)), Color(0.0));
  const Scene spheres = make_cornell_spheres();
  EXPECT_NEAR(spheres.point_light.intensity_towards(Vec3(0, -1, 0)).r,
              12.0 * k_two_pi * 600.0 * 0.27, 1e-9);
  EXPECT_LT(spheres.point_light.position.y, 81.6 - 0.27);  // inside the room, under the cap
  // With no normal the light is isotropic.
  const PointLight isotropic{Vec3(0.0), Color(2.0), Vec3(0.0)};
  EXPECT_EQ(isotropic.intensity_towards(Vec3(0, 1, 0)), Color(2.0));
}

TEST(SceneTest, TheLampEmitsDownwardsOnly) {
  const Scene scene = make_cornell_box();
  // From below, the lamp; from the gap between lamp and ceiling, looking down, its black back.
  const auto up = scene.closest_hit({{278, 1, 278}, {0, 1, 0}});
  ASSERT_TRUE(up);
  EXPECT_EQ(scene.material(*up).emission, Color(15.0));
  const auto down = scene.closest_hit({{278, 554.5, 278}, {0, -1, 0}});
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->point.y, 554.0, 1e-9);
  EXPECT_EQ(scene.material(*down).emission, Color(0.0));
  EXPECT_EQ(scene.material(*down).albedo, Color(0.0));
}

TEST(SceneTest, LightScaleKeepsThePowerAndTheCentre) {
  for (double s : {0.1, 1.0, 3.0}) {
    SceneParams params;
    params.light_scale = s;
    const Scene scene = make_scene("cornell", params);
    ASSERT_EQ(scene.emitters().size(), 1u);
    const Emitter& e = scene.emitters()[0];
    EXPECT_EQ(e.kind, Emitter::quad);
    EXPECT_TRUE(e.one_sided);
    const Quad& lamp = scene.quads()[e.index];
    const double le = scene.materials[lamp.material()].emission.r;
    EXPECT_NEAR(le * lamp.area(), 15.0 * 130.0 * 105.0, 1e-6) << s;  // power / pi
    EXPECT_NEAR(glm::length(lamp.center() - Vec3(278, 554, 279.5)), 0.0, 1e-9) << s;
    EXPECT_EQ(lamp.normal(), Vec3(0, -1, 0));
  }
  SceneParams too_big;
  too_big.light_scale = 4.5;
  EXPECT_THROW(make_scene("cornell", too_big), std::invalid_argument);
}

TEST(SceneTest, EverySceneKnowsItsEmitters) {
  const Scene spheres = make_cornell_spheres();
  ASSERT_EQ(spheres.emitters().size(), 1u);
  EXPECT_EQ(spheres.emitters()[0].kind, Emitter::sphere);
  EXPECT_EQ(spheres.emitters()[0].index, 8u);
  EXPECT_TRUE(spheres.emitters()[0].has_enclosure);
  // The ceiling curves down away from its axis, so the light's part inside it is a little
  // shallower than the 0.27 below the ceiling's plane: (d^2 - rho^2 + R^2) / 2d from the centre.
  EXPECT_NEAR(spheres.emitters()[0].cap_height, 0.268390020, 1e-8);
  const Scene furnace = make_furnace(0.5, 1.0);
  ASSERT_EQ(furnace.emitters().size(), 1u);
  EXPECT_EQ(furnace.emitters()[0].cap_height, 2.0);  // the whole unit sphere
  EXPECT_FALSE(furnace.emitters()[0].one_sided);
}

// The cap the scene computes is exactly the light's part inside its enclosure (the ceiling):
// points of the light sphere are inside the ceiling's ball if and only if they are on the cap
// (away from its rim, where round-off decides).
TEST(SceneTest, SphereLightCapIsItsPartInsideTheEnclosure) {
  const Scene scene = make_cornell_spheres();
  const Emitter& e = scene.emitters()[0];
  const Sphere& light = scene.spheres()[e.index];
  const double z_rim = 1.0 - e.cap_height / light.radius;
  Rng rng(3, 0);
  int inside = 0;
  for (int i = 0; i < 200000; ++i) {
    // Points on the light's lowest 0.6 units, where the cap's rim lies.
    const Vec2 u = rng.uniform2();
    const LightPoint y = sample_sphere_cap(light.center, light.radius, e.cap_axis, 0.6, u);
    const double z = glm::dot(y.point - light.center, e.cap_axis) / light.radius;
    const double rho = glm::length(y.point - e.enclosure.center) - e.enclosure.radius;
    if (std::abs(z - z_rim) < 1e-9) continue;
    EXPECT_EQ(z > z_rim, rho < 0.0) << "z " << z << ", distance outside the ceiling " << rho;
    inside += rho < 0.0;
  }
  EXPECT_GT(inside, 80000);  // the cap is 0.268 of the 0.6 sampled: about 89000
}

}  // namespace
