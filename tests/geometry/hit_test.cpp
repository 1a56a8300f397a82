// spawn_ray and spawn_ray_to (geometry/hit.hpp): the offset that moves a new ray off its
// surface, on the side of its direction, and the minimum distance a ray sees.

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/hit.hpp"
#include "geometry/quad.hpp"
#include "geometry/sphere.hpp"

using namespace mcrt;

namespace {

// Distances are exact up to a few ulps of the coordinates involved.
constexpr double k_tol = 1e-12;

const Sphere k_unit{Vec3(0.0), 1.0, 7};
const Quad k_square{{-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 3};

TEST(SpawnRayTest, LeavesTheSurfaceOnTheSideOfTheDirection) {
  Hit hit;
  hit.point = {0, 0, 0};
  hit.normal = {0, 0, 1};
  const Ray up = spawn_ray(hit, {0, 0, 1});
  EXPECT_GT(up.origin.z, 0.0);
  EXPECT_FALSE(intersect_distance(k_square, up, {}));
  const Ray down = spawn_ray(hit, {0, 0, -1});
  EXPECT_LT(down.origin.z, 0.0);
  EXPECT_FALSE(intersect_distance(k_square, down, {}));
}

TEST(SpawnRayTest, ReboundOffAWallSphereDoesNotHitItAgain) {
  // smallpt's left wall: the plane x = 1 is the near pole of a ball that holds the whole room.
  const Sphere wall{{1e5 + 1, 40.8, 81.6}, 1e5, 0};
  const Ray in{{50, 40, 80}, glm::normalize(Vec3(-1, 0.1, 0.05))};
  const auto hit = intersect(wall, in, {});
  ASSERT_TRUE(hit);
  // On the sphere to ~1e-10 relative: the round-off of coordinates of size 1e5.
  EXPECT_NEAR(glm::length(hit->point - wall.center), wall.radius, 1e-5);
  // Back into the room: the next hit is the ball's far side, 2e5 away, never the wall itself.
  const Ray out = spawn_ray(*hit, glm::normalize(Vec3(1, 0.3, -0.2)));
  const auto next = intersect_distance(wall, out, {});
  ASSERT_TRUE(next);
  EXPECT_GT(*next, 1e5);
}

TEST(SpawnRayTest, ToTargetReturnsTheRemainingDistance) {
  Hit hit;
  hit.point = {0, 0, 0};
  hit.normal = {0, 0, 1};
  const auto [ray, distance] = spawn_ray_to(hit, {0, 0, 10});
  EXPECT_NEAR(distance + ray.origin.z, 10.0, k_tol);
  EXPECT_NEAR(glm::length(ray.direction), 1.0, k_tol);
}

// The shadow ray passes through its target: a light point 5 units away, seen at a slant from
// a point at the sphere box's scale (push-off 1.5e-5), is reached at the returned distance,
// not a push-off before it (where the light's own surface would block the ray).
TEST(SpawnRayTest, ToTargetPassesThroughTheTarget) {
  Hit hit;
  hit.point = {72.8, 81.574, 150.0};
  hit.normal = {0, 1, 0};
  const Vec3 target(69.0, 85.0, 146.0);
  const auto [ray, distance] = spawn_ray_to(hit, target);
  EXPECT_GT(ray.origin.y, hit.point.y);
  EXPECT_NEAR(glm::length(ray.origin + distance * ray.direction - target), 0.0, 1e-12);
}

// The minimum distance a ray sees, pinned: a surface 5e-7 ahead of a ray's origin is hit
// (Interval's t_min is 1e-9), and so is one 5e-7 beyond a hit point near the origin, where
// spawn_ray's push-off is 1e-7 (1 + |p|) = 2e-7: a thin shell of glass is not skipped.
TEST(SpawnRayTest, ASurfaceFiveTenthsOfAMicronAheadIsHit) {
  const Sphere near_surface{{0, 0, 1.0 + 5e-7}, 1.0, 0};
  const auto t = intersect_distance(near_surface, {{0, 0, 0}, {0, 0, 1}}, {});
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 5e-7, 1e-15);

  const Sphere inner{Vec3(0.0), 1.0, 0}, outer{Vec3(0.0), 1.0 + 5e-7, 0};
  const auto hit = intersect(inner, {{0, 0, -3}, {0, 0, 1}}, {});
  ASSERT_TRUE(hit);
  const Ray back_out = spawn_ray(*hit, {0, 0, -1});  // reflected off the inner sphere
  const auto shell = intersect_distance(outer, back_out, {});
  ASSERT_TRUE(shell);
  EXPECT_NEAR(back_out.origin.z + -*shell, -1.0 - 5e-7, 1e-15);
  EXPECT_FALSE(intersect_distance(inner, back_out, {}));  // and not the surface it left
}

// Glass: a ray refracted into a sphere starts a push-off inside it and meets the far side
// (a chord away), never the point where it entered; the ray that leaves again starts outside.
TEST(SpawnRayTest, ARayIntoASphereMeetsItsFarSideFromInside) {
  for (double radius : {1.0, 16.5, 1e5}) {
    const Sphere ball{{0.3, -0.2, 0.1}, radius, 0};
    const Vec3 o = ball.center + Vec3(0, 0, -3.0 * radius);
    for (double b : {0.0, 0.5, 0.9, 0.999}) {
      const Ray in{o, glm::normalize(ball.center + Vec3(b * radius, 0, 0) - o)};
      const auto entry = intersect(ball, in, {});
      ASSERT_TRUE(entry);
      EXPECT_TRUE(entry->front_face);
      // Bent towards the centre, as glass would (any direction into the ball will do).
      const Vec3 inward = glm::normalize(in.direction + 0.3 * -entry->normal);
      const Ray inside = spawn_ray(*entry, inward);
      EXPECT_LT(glm::length(inside.origin - ball.center), radius);
      const auto exit = intersect(ball, inside, {});
      ASSERT_TRUE(exit);
      EXPECT_FALSE(exit->front_face);
      EXPECT_GT(exit->t, 1e-3 * radius) << radius << " " << b;   // the far side, not the entry
      EXPECT_LT(glm::dot(exit->normal, inside.direction), 0.0);  // the normal faces the ray
      const Ray out = spawn_ray(*exit, inside.direction);
      EXPECT_GT(glm::length(out.origin - ball.center), radius);
      EXPECT_FALSE(intersect_distance(ball, out, {}));  // gone: a convex ball is left for good
    }
  }
}

// Exactly tangent rays touch the sphere at one point (det = 0), on its outside (front_face,
// the normal outwards); a ray that leaves a tangent point along the tangent is pushed off
// outwards and sees the sphere no more (pushed inwards it met the sphere again 6e-4 on).
TEST(SpawnRayTest, ATangentRayTouchesOnceAndGoesOn) {
  const Ray tangent{{-5, 1, 0}, {1, 0, 0}};
  const auto hit = intersect(k_unit, tangent, {});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->t, 5.0);
  EXPECT_EQ(hit->point, Vec3(0, 1, 0));
  EXPECT_EQ(glm::dot(hit->normal, tangent.direction), 0.0);
  EXPECT_TRUE(hit->front_face);
  EXPECT_EQ(hit->normal, Vec3(0, 1, 0));
  const Ray onwards = spawn_ray(*hit, tangent.direction);
  EXPECT_FALSE(intersect_distance(k_unit, onwards, {}));
}

}  // namespace
