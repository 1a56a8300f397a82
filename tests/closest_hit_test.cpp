// Scene::closest_hit, written for speed, against the plain loop over every primitive's
// intersect_distance: the same hit, bit for bit, for rays from anywhere and any range.

#include <gtest/gtest.h>

#include <optional>

#include "rng.hpp"
#include "sampling.hpp"
#include "scene.hpp"

using namespace mcrt;

namespace {

std::optional<Hit> plain_closest_hit(const Scene& scene, const Ray& ray, Interval range) {
  std::optional<Hit> hit;
  for (const Sphere& s : scene.spheres)
    if (const auto t = intersect_distance(s, ray, range)) {
      range.max = *t;
      hit = hit_at(s, ray, *t);
    }
  for (const Quad& q : scene.quads)
    if (const auto t = intersect_distance(q, ray, range)) {
      range.max = *t;
      hit = hit_at(q, ray, *t);
    }
  return hit;
}

TEST(ClosestHitTest, SameHitAsThePlainLoopBitForBit) {
  for (const std::string& name : scene_names()) {
    const Scene scene = make_scene(name);
    Rng rng(11, 0);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
      // Origins inside and around every scene (the walls of cornell-spheres are 1e5 away).
      const double scale = name == "furnace" ? 1.5 : 700.0;
      const Vec3 origin = scale * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.3);
      const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
      const Ray ray{origin, rng.uniform() < 0.5 ? local : -local};
      const Interval range = i % 3 == 0 ? Interval{} : Interval{scale * 0.1 * rng.uniform(),
                                                                scale * 2.0 * rng.uniform()};
      const std::optional<Hit> fast = scene.closest_hit(ray, range);
      const std::optional<Hit> plain = plain_closest_hit(scene, ray, range);
      ASSERT_EQ(fast.has_value(), plain.has_value()) << name << " ray " << i;
      if (!fast) continue;
      ++hits;
      EXPECT_EQ(fast->t, plain->t);
      EXPECT_EQ(fast->point, plain->point);
      EXPECT_EQ(fast->normal, plain->normal);
      EXPECT_EQ(fast->material, plain->material);
    }
    EXPECT_GT(hits, 300) << name;  // the comparison saw real hits
  }
}

}  // namespace
