// Ray-quad intersection: both faces, edges, parallel rays, t_min, and the plane-offset form of
// the hit distance against the hit-point form it replaced.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "geometry/quad.hpp"

using namespace mcrt;

namespace {

// Hit distances are exact up to a few ulps of the coordinates involved.
constexpr double k_tol = 1e-12;

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
  EXPECT_TRUE(intersect_distance(k_square, {{1.0, 0.0, 1}, {0, 0, -1}}, {}));  // on an edge
  EXPECT_FALSE(intersect_distance(k_square, {{1.001, 0.0, 1}, {0, 0, -1}}, {}));
  EXPECT_FALSE(intersect_distance(k_square, {{0, -1.5, 1}, {0, 0, -1}}, {}));
}

TEST(QuadTest, ParallelAndBehindRaysMiss) {
  EXPECT_FALSE(intersect_distance(k_square, {{0, 0, 0}, {1, 0, 0}}, {}));  // in the plane
  EXPECT_FALSE(intersect_distance(k_square, {{0, 0, 1}, {0, 1, 0}}, {}));  // parallel above
  EXPECT_FALSE(intersect_distance(k_square, {{0, 0, 1}, {0, 0, 1}}, {}));  // plane behind
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
    return length *
           glm::normalize(Vec3(signed_unit(random), signed_unit(random), signed_unit(random)));
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
    const double t_plane =
        glm::dot(q.plane_normal(), q.corner() - origin) / glm::dot(q.plane_normal(), ray.direction);
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
    const double bound =
        2.0 * 8.0 * 0x1p-53 * (glm::length(q.corner()) + glm::length(origin)) / cosine;
    EXPECT_NEAR(*after, *before, bound) << "quad " << i;
  }
  // Floors, so the comparison cannot pass empty: the fixed seed gives far more.
  EXPECT_GT(compared, 10000);
  EXPECT_GT(hits, 1500);  // 2175
}

}  // namespace
