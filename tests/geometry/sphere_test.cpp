// Ray-sphere intersection: near and far sides, tangents, the interval, and smallpt's huge wall
// spheres.

#include <gtest/gtest.h>

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

}  // namespace
