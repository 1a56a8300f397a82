// The built-in scenes and the closest-hit / any-hit queries.

#include <gtest/gtest.h>

#include "core/rng.hpp"
#include "render/scene.hpp"
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

TEST(SceneTest, PointLightCarriesTheAreaLightsPower) {
  // I = Le A / 4 (power pi Le A of a one-sided area light, spread over 4 pi steradians).
  const Scene box = make_cornell_box();
  EXPECT_NEAR(box.point_light.intensity.r, 15.0 * 130.0 * 105.0 / 4.0, 1e-9);
  const Scene spheres = make_cornell_spheres();
  EXPECT_NEAR(spheres.point_light.intensity.r, 12.0 * k_two_pi * 600.0 * 0.27 / 4.0, 1e-9);
  EXPECT_LT(spheres.point_light.position.y, 81.6 - 0.27);  // inside the room, under the cap
}

}  // namespace
