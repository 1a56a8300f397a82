// Ray-sphere and ray-quad intersection, and the offset that moves new rays off a surface.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "geometry/hit.hpp"
#include "geometry/quad.hpp"
#include "geometry/sphere.hpp"

using namespace mcrt;

namespace {

// Hit distances are exact up to a few ulps of the coordinates involved.
constexpr double k_tol = 1e-12;

const Sphere k_unit{Vec3(0.0), 1.0, 7};

TEST(SphereTest, HitFromOutsideIsTheNearSide) {
  const Ray ray{{0, 0, -5}, {0, 0, 1}};
  const auto hit = intersect(k_unit, ray, {});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 4.0, k_tol);
  EXPECT_NEAR(hit->point.z, -1.0, k_tol);
  EXPECT_EQ(hit->normal, Vec3(0, 0, -1));  // faces the incoming ray
  EXPECT_EQ(hit->material, 7u);
}

TEST(SphereTest, HitFromInsideIsTheFarSideWithNormalFacingIn) {
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  const auto hit = intersect(k_unit, ray, {});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 1.0, k_tol);
  EXPECT_EQ(hit->normal, Vec3(-1, 0, 0));
}

TEST(SphereTest, TangentRayTouchesOnce) {
  const Ray ray{{-5, 1, 0}, {1, 0, 0}};
  const auto t = intersect_distance(k_unit, ray, {});
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 5.0, k_tol);
}

TEST(SphereTest, MissesWhenPassingBesideOrBehindTheOrigin) {
  EXPECT_FALSE(intersect_distance(k_unit, {{-5, 1.01, 0}, {1, 0, 0}}, {}));
  EXPECT_FALSE(intersect_distance(k_unit, {{0, 0, 5}, {0, 0, 1}}, {}));  // sphere behind
}

TEST(SphereTest, RespectsTheInterval) {
  const Ray ray{{0, 0, -5}, {0, 0, 1}};
  EXPECT_NEAR(*intersect_distance(k_unit, ray, {4.5, 100.0}), 6.0, k_tol);  // far side
  EXPECT_FALSE(intersect_distance(k_unit, ray, {0.0, 3.9}));
  EXPECT_FALSE(intersect_distance(k_unit, ray, {6.1, 100.0}));
}

TEST(SphereTest, HugeWallSphereIsAccurate) {
  // A floor of radius 1e5 with its top at y = 0, and smallpt's ceiling seen from inside.
  // With radius 1e5 the cancellation in |c - o|^2 - r^2 costs about 1e10 * 2^-52 ~ 2e-6 in
  // b^2 - c, so t is good to ~1e-9 at these distances: far below any visible effect.
  const Sphere floor{{50, -1e5, 81.6}, 1e5, 0};
  EXPECT_NEAR(*intersect_distance(floor, {{50, 40, 81.6}, {0, -1, 0}}, {}), 40.0, 1e-9);
  const Sphere ceiling{{50, -1e5 + 81.6, 81.6}, 1e5, 0};
  EXPECT_NEAR(*intersect_distance(ceiling, {{50, 40, 81.6}, {0, 1, 0}}, {}), 41.6, 1e-9);
}

const Quad k_square{{-1, -1, 0}, {2, 0, 0}, {0, 2, 0}, 3};

TEST(QuadTest, FrontAndBackHits) {
  const auto front = intersect(k_square, {{0.5, 0.5, 2}, {0, 0, -1}}, {});
  ASSERT_TRUE(front);
  EXPECT_NEAR(front->t, 2.0, k_tol);
  EXPECT_EQ(front->normal, Vec3(0, 0, 1));
  const auto back = intersect(k_square, {{0.5, 0.5, -2}, {0, 0, 1}}, {});
  ASSERT_TRUE(back);
  EXPECT_EQ(back->normal, Vec3(0, 0, -1));
  EXPECT_EQ(back->material, 3u);
}

TEST(QuadTest, EdgesAndOutside) {
  EXPECT_TRUE(intersect_distance(k_square, {{1.0, 0.0, 1}, {0, 0, -1}}, {}));   // on an edge
  EXPECT_FALSE(intersect_distance(k_square, {{1.001, 0.0, 1}, {0, 0, -1}}, {}));
  EXPECT_FALSE(intersect_distance(k_square, {{0, -1.5, 1}, {0, 0, -1}}, {}));
}

TEST(QuadTest, ParallelAndBehindRaysMiss) {
  EXPECT_FALSE(intersect_distance(k_square, {{0, 0, 0}, {1, 0, 0}}, {}));   // in the plane
  EXPECT_FALSE(intersect_distance(k_square, {{0, 0, 1}, {0, 1, 0}}, {}));   // parallel above
  EXPECT_FALSE(intersect_distance(k_square, {{0, 0, 1}, {0, 0, 1}}, {}));   // plane behind
}

TEST(QuadTest, TMinExcludesTheOrigin) {
  const Ray ray{{0, 0, 0}, {0, 0, 1}};  // starts on the quad
  EXPECT_FALSE(intersect_distance(k_square, ray, {}));
}

TEST(QuadTest, AreaNormalCentre) {
  EXPECT_DOUBLE_EQ(k_square.area(), 4.0);
  EXPECT_EQ(k_square.normal(), Vec3(0, 0, 1));
  EXPECT_EQ(k_square.center(), Vec3(0, 0, 0));
}

// intersect_distance finds t from the plane's offset and the edge coordinates as linear
// functions along the ray. The form it replaced went through the hit point:
// t = n.(corner - o) / n.d, then a = axis_a.(o + t d - corner). The two round differently
// (which changed every image's last bits), so they must agree within that rounding: on
// Cornell-sized quads (coordinates up to 600), rays at least 1 from the plane and at least
// 0.1 from parallel, each numerator carries about 8 roundings of terms up to
// |n|(|corner| + |o|), so |dt| <= 8 eps (|corner| + |o|) / |cos| (eps = 2^-53). The test
// allows twice that (at this seed the largest difference is 0.13 of the allowance). Hit or
// miss must agree wherever the old a and b are 1e-9 or more inside or outside [0, 1] (their
// rounding is below 1e-12 here).
std::optional<double> hit_point_form(const Quad& q, const Ray& ray, Interval range) {
  const Vec3& n = q.plane_normal();
  const double denom = glm::dot(n, ray.direction);
  if (std::abs(denom) < q.parallel_threshold()) return std::nullopt;
  const double t = glm::dot(n, q.corner() - ray.origin) / denom;
  if (!range.contains(t)) return std::nullopt;
  const Vec3 p = ray.at(t) - q.corner();
  const double a = q.coordinate_a(p), b = q.coordinate_b(p);
  if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return std::nullopt;
  return t;
}

TEST(QuadTest, PlaneOffsetFormAgreesWithTheHitPointForm) {
  std::mt19937_64 random(20261203);
  std::uniform_real_distribution<double> coordinate(0.0, 600.0), signed_unit(-1.0, 1.0);
  auto point = [&] { return Vec3(coordinate(random), coordinate(random), coordinate(random)); };
  auto vector = [&](double length) {
    return length * glm::normalize(Vec3(signed_unit(random), signed_unit(random),
                                        signed_unit(random)));
  };
  int hits = 0, compared = 0;
  for (int i = 0; i < 20000; ++i) {
    const Quad q{point(), vector(50.0 + 300.0 * (signed_unit(random) + 1.0)),
                 vector(50.0 + 300.0 * (signed_unit(random) + 1.0))};
    // A ray aimed at a point near the quad: about half hit it.
    const Vec3 target = q.corner() + (1.4 * signed_unit(random) + 0.5) * q.edge_u() +
                        (1.4 * signed_unit(random) + 0.5) * q.edge_v();
    const Vec3 origin = point();
    const Ray ray{origin, glm::normalize(target - origin)};
    const double cosine = std::abs(glm::dot(q.normal(), ray.direction));
    const double distance = std::abs(glm::dot(q.normal(), q.corner() - origin));
    if (cosine < 0.1 || distance < 1.0) continue;
    ++compared;
    // Where the old form puts the point, in edge coordinates.
    const double t_plane = glm::dot(q.plane_normal(), q.corner() - origin) /
                           glm::dot(q.plane_normal(), ray.direction);
    const Vec3 p = ray.at(t_plane) - q.corner();
    const double a = q.coordinate_a(p), b = q.coordinate_b(p);
    const double margin =
        std::min({std::abs(a), std::abs(a - 1.0), std::abs(b), std::abs(b - 1.0)});
    const auto before = hit_point_form(q, ray, {});
    const auto after = intersect_distance(q, ray, {});
    if (margin >= 1e-9) {
      ASSERT_EQ(before.has_value(), after.has_value()) << "quad " << i;
    }
    if (!before || !after) continue;
    ++hits;
    const double bound = 2.0 * 8.0 * 0x1p-53 *
                         (glm::length(q.corner()) + glm::length(origin)) / cosine;
    EXPECT_NEAR(*after, *before, bound) << "quad " << i;
  }
  // Floors, so the comparison cannot pass empty: the fixed seed gives far more.
  EXPECT_GT(compared, 10000);
  EXPECT_GT(hits, 1500);  // 2175
}

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
      EXPECT_GT(exit->t, 1e-3 * radius) << radius << " " << b;  // the far side, not the entry
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
