// Geometry from every direction (issue #17, part 3): frames, intersections and spawned rays
// tested as properties over generated cases, not a few hand-picked ones. The generator gives
// directions from all eight octants, the axes and their neighbourhoods (n.z = -1 is the
// frame's singular point), the equator, normals with n.z < 0 and a sizeable n.x, and rays at
// grazing angles (cos from 1e-4 up) to the surface they hit.
//
// The references are independent: intersections are solved again in long double (the
// sphere's quadratic written as t^2 + 2 B t + C, the quad as a 3 x 3 linear system by
// Cramer's rule), and each property states its tolerance and why.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "geometry/quad.hpp"
#include "geometry/sphere.hpp"
#include "sampling/sampling.hpp"

using namespace mcrt;

namespace {

// ---------------------------------------------------------------------------------------------
// The generator.

/// Unit directions: every octant's diagonal, the six axes, the axes nudged by 1e-12 .. 1e-3 in
/// every octant, points on the equators, and `random` uniform directions from every octant.
std::vector<Vec3> direction_cases(Rng& rng, int random) {
  std::vector<Vec3> cases;
  for (int octant = 0; octant < 8; ++octant) {
    const Vec3 sign((octant & 1) ? -1.0 : 1.0, (octant & 2) ? -1.0 : 1.0,
                    (octant & 4) ? -1.0 : 1.0);
    cases.push_back(glm::normalize(sign));
    for (int axis = 0; axis < 3; ++axis)
      for (double nudge : {1e-12, 1e-8, 1e-5, 1e-3}) {
        Vec3 d = nudge * sign;
        d[axis] = sign[axis];
        cases.push_back(glm::normalize(d));
      }
    // n.z < 0 (or > 0) with a sizeable n.x: the case the hand-picked frame test lacked.
    cases.push_back(glm::normalize(Vec3(0.9 * sign.x, 0.1 * sign.y, 0.4 * sign.z)));
    cases.push_back(glm::normalize(Vec3(sign.x, 1e-9 * sign.y, 1e-9 * sign.z)));  // equator
  }
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) {
      Vec3 d(0.0);
      d[axis] = s;
      cases.push_back(d);
    }
  for (int i = 0; i < random; ++i) {
    Vec3 d = sample_uniform_sphere(rng.uniform2());
    // Move it into octant i mod 8, so every octant gets its share.
    d = Vec3(std::abs(d.x), std::abs(d.y), std::abs(d.z));
    if (i & 1) d.x = -d.x;
    if (i & 2) d.y = -d.y;
    if (i & 4) d.z = -d.z;
    cases.push_back(d);
  }
  return cases;
}

/// A unit direction making angle acos(cos_theta) with unit n, at a random azimuth.
Vec3 direction_at(const Vec3& n, double cos_theta, Rng& rng) {
  const double phi = 2.0 * k_pi * rng.uniform();
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  // A basis built here (not with Frame, which is under test): any vector not parallel to n.
  const Vec3 helper = std::abs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 t = glm::normalize(glm::cross(n, helper));
  const Vec3 b = glm::cross(n, t);
  return glm::normalize(sin_theta * (std::cos(phi) * t + std::sin(phi) * b) + cos_theta * n);
}

/// cos theta from grazing to straight on: 1e-4 .. 1 log-uniformly, so grazing angles are
/// common.
double random_cos(Rng& rng) { return std::pow(10.0, -4.0 * rng.uniform()); }

// ---------------------------------------------------------------------------------------------
// Frames.

TEST(FramePropertyTest, OrthonormalRightHandedBasisAroundEveryNormal) {
  Rng rng(1, 0);
  int cases = 0;
  for (const Vec3& n : direction_cases(rng, 4000)) {
    const Frame frame(n);
    // Duff et al.'s basis is exact up to a few ulps everywhere except at n.z = -1, where it
    // switches branch; 1e-12 is a hundred times the round-off of these products.
    EXPECT_EQ(frame.normal, n);
    EXPECT_NEAR(glm::length(frame.tangent), 1.0, 1e-12) << n.x << " " << n.y << " " << n.z;
    EXPECT_NEAR(glm::length(frame.bitangent), 1.0, 1e-12) << n.x << " " << n.y << " " << n.z;
    EXPECT_NEAR(glm::dot(frame.tangent, frame.bitangent), 0.0, 1e-12)
        << n.x << " " << n.y << " " << n.z;
    EXPECT_NEAR(glm::dot(frame.tangent, n), 0.0, 1e-12) << n.x << " " << n.y << " " << n.z;
    EXPECT_NEAR(glm::dot(frame.bitangent, n), 0.0, 1e-12) << n.x << " " << n.y << " " << n.z;
    // Right-handed: t x b = n, so local directions keep their orientation in every frame.
    EXPECT_NEAR(glm::length(glm::cross(frame.tangent, frame.bitangent) - n), 0.0, 1e-12)
        << n.x << " " << n.y << " " << n.z;
    // A local direction keeps its length and its cosine to the normal.
    const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
    const Vec3 world = frame.to_world(local);
    EXPECT_NEAR(glm::length(world), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(world, n), local.z, 1e-12);
    ++cases;
  }
  EXPECT_GT(cases, 4100);
}

// ---------------------------------------------------------------------------------------------
// Spheres.

struct SphereCase {
  Sphere sphere;
  Ray ray;
};

/// A sphere of radius 1e-1 .. 1e5 (log-uniform) with its centre within 10 radii of the origin,
/// and a ray from outside aimed at it from any octant (or, one time in four, from inside).
SphereCase random_sphere_case(Rng& rng, const Vec3& direction) {
  const double r = std::pow(10.0, -1.0 + 6.0 * rng.uniform());
  const Sphere sphere{10.0 * r * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5), r, 0};
  const bool inside = rng.uniform() < 0.25;
  // Outside: start 1.5 .. 20 radii from the centre, against `direction`, offset sideways
  // by up to 1.2 r so some rays miss and some graze.
  const double back = inside ? 0.0 : r * (1.5 + 18.5 * rng.uniform());
  const Vec3 side = direction_at(direction, 0.0, rng) *
                    (inside ? 0.9 * r * rng.uniform() : 1.2 * r * rng.uniform());
  return {sphere, {sphere.center - back * direction + side, direction}};
}

// Roots of |o + t d - c| = r in long double: t = -B -+ sqrt(B^2 - C), B = d.(o - c),
// C = |o - c|^2 - r^2; the nearer root in (min, max) first.
struct RootsLd {
  bool real;
  long double near, far, discriminant;
};
RootsLd sphere_roots(const Sphere& s, const Ray& ray) {
  const long double ox = static_cast<long double>(ray.origin.x) - s.center.x;
  const long double oy = static_cast<long double>(ray.origin.y) - s.center.y;
  const long double oz = static_cast<long double>(ray.origin.z) - s.center.z;
  const long double B = ox * ray.direction.x + oy * ray.direction.y + oz * ray.direction.z;
  const long double r = s.radius;
  const long double C = ox * ox + oy * oy + oz * oz - r * r;
  const long double D = B * B - C;
  if (D < 0) return {false, 0, 0, D};
  const long double root = std::sqrt(D);
  return {true, -B - root, -B + root, D};
}

TEST(SpherePropertyTest, HitsAgreeWithAnIndependentSolutionFromEveryDirection) {
  Rng rng(2, 0);
  int hits = 0, misses = 0, compared = 0;
  for (const Vec3& d : direction_cases(rng, 6000)) {
    const auto [sphere, ray] = random_sphere_case(rng, d);
    const double r = sphere.radius;
    const double oc = glm::length(ray.origin - sphere.center);
    const RootsLd roots = sphere_roots(sphere, ray);
    // Near tangency (|B^2 - C| < 1e-6 r^2) hit or miss is decided by round-off: skip.
    if (std::abs(static_cast<double>(roots.discriminant)) < 1e-6 * r * r) continue;
    ++compared;
    const std::optional<Hit> hit = intersect(sphere, ray, {});
    const bool expected = roots.real && roots.far > 1e-9L * r;
    ASSERT_EQ(hit.has_value(), expected)
        << "radius " << r << " direction " << d.x << " " << d.y << " " << d.z;
    if (!hit) {
      ++misses;
      continue;
    }
    ++hits;
    const double t = static_cast<double>(roots.near > 1e-9L * r ? roots.near : roots.far);
    // t to the round-off of b^2 - |oc|^2 + r^2 (eps (|oc| + r)^2, over a root >= 1e-3 r here).
    const double tol = 1e-11 * ((oc + r) * (oc + r) / r + oc + glm::length(sphere.center));
    EXPECT_NEAR(hit->t, t, tol) << "radius " << r;
    // On the sphere, with a unit normal facing the incoming ray.
    EXPECT_NEAR(glm::length(hit->point - sphere.center), r, tol);
    EXPECT_NEAR(glm::length(hit->normal), 1.0, 1e-12);
    EXPECT_LE(glm::dot(hit->normal, ray.direction), 0.0);
    EXPECT_NEAR(std::abs(glm::dot(hit->normal, glm::normalize(hit->point - sphere.center))), 1.0,
                1e-9);
  }
  EXPECT_GT(hits, 2000);
  EXPECT_GT(misses, 500);
  EXPECT_GT(compared, 5000);
}

// A ray spawned off a sphere never hits that sphere at its own origin: leaving the side away
// from the centre it misses the (convex) sphere altogether; entering it, its next hit is the
// far side, at least half the chord 2 r cos away (the offset, 1e-7 of the coordinates, is far
// smaller than r cos >= 1e-4 r for centres within 10 radii).
TEST(SpherePropertyTest, SpawnedRaysNeverHitTheirOwnSurface) {
  Rng rng(3, 0);
  int leaving = 0, entering = 0;
  for (const Vec3& d : direction_cases(rng, 6000)) {
    const auto [sphere, ray] = random_sphere_case(rng, d);
    const std::optional<Hit> hit = intersect(sphere, ray, {});
    if (!hit) continue;
    const Vec3 outward = glm::normalize(hit->point - sphere.center);
    const double cos_theta = random_cos(rng);
    const bool leave = rng.uniform() < 0.5;
    const Vec3 wi = direction_at(leave ? outward : -outward, cos_theta, rng);
    const Ray spawned = spawn_ray(*hit, wi);
    // The origin moved to the side the direction goes.
    EXPECT_GT(glm::dot(spawned.origin - hit->point, hit->normal) * glm::dot(wi, hit->normal), 0.0);
    const auto next = intersect_distance(sphere, spawned, {});
    if (leave) {
      ++leaving;
      EXPECT_FALSE(next) << "radius " << sphere.radius << " cos " << cos_theta << " t "
                         << next.value_or(0.0);
    } else {
      ++entering;
      ASSERT_TRUE(next) << "radius " << sphere.radius << " cos " << cos_theta;
      EXPECT_GT(*next, sphere.radius * cos_theta)
          << "radius " << sphere.radius << " cos " << cos_theta;
    }
  }
  EXPECT_GT(leaving, 1500);
  EXPECT_GT(entering, 1500);
}

// ---------------------------------------------------------------------------------------------
// Quads.

/// A parallelogram of side 1e-2 .. 1e3 in any orientation, its corner within 100 sides of
/// the origin.
Quad random_quad(Rng& rng) {
  const double size = std::pow(10.0, -2.0 + 5.0 * rng.uniform());
  const Vec3 n = sample_uniform_sphere(rng.uniform2());
  const Vec3 u = size * (0.3 + rng.uniform()) * direction_at(n, 0.0, rng);
  // v: in the plane, 20 .. 160 degrees from u (sheared parallelograms too).
  const double angle = k_pi * (0.11 + 0.78 * rng.uniform());
  const Vec3 w = glm::normalize(glm::cross(n, u));
  const Vec3 v =
      size * (0.3 + rng.uniform()) * (std::cos(angle) * glm::normalize(u) + std::sin(angle) * w);
  const Vec3 corner = 100.0 * size * (Vec3(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5);
  return Quad(corner, u, v, 1);
}

// o + t d = corner + a u + b v, solved by Cramer's rule in long double: [u v -d] (a b t) = o - corner.
struct QuadSolution {
  long double a, b, t, det;
};
QuadSolution solve_quad(const Quad& q, const Ray& ray) {
  using L = long double;
  const L m[3][3] = {{q.edge_u().x, q.edge_v().x, -ray.direction.x},
                     {q.edge_u().y, q.edge_v().y, -ray.direction.y},
                     {q.edge_u().z, q.edge_v().z, -ray.direction.z}};
  const L rhs[3] = {L(ray.origin.x) - q.corner().x, L(ray.origin.y) - q.corner().y,
                    L(ray.origin.z) - q.corner().z};
  auto det3 = [](const L a[3][3]) {
    return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
           a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
           a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  };
  const L det = det3(m);
  L x[3];
  for (int col = 0; col < 3; ++col) {
    L mc[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) mc[i][j] = j == col ? rhs[i] : m[i][j];
    x[col] = det3(mc) / det;
  }
  return {x[0], x[1], x[2], det};
}

TEST(QuadPropertyTest, HitsAgreeWithAnIndependentSolutionFromEveryDirection) {
  Rng rng(4, 0);
  int hits = 0, misses = 0, compared = 0;
  for (const Vec3& d : direction_cases(rng, 6000)) {
    const Quad q = random_quad(rng);
    const double size = std::sqrt(q.area());
    // Aim at a point of the quad's plane with edge coordinates in [-0.3, 1.3]^2 (so some rays
    // miss), from 0.1 .. 10 sizes away; directions from every octant, grazing ones included.
    const double a = -0.3 + 1.6 * rng.uniform(), b = -0.3 + 1.6 * rng.uniform();
    const Vec3 target = q.corner() + a * q.edge_u() + b * q.edge_v();
    const Ray ray{target - size * (0.1 + 9.9 * rng.uniform()) * d, d};
    const QuadSolution s = solve_quad(q, ray);
    // Skip what round-off decides: edge coordinates within 1e-6 of an edge, or a ray within
    // 1e-9 of parallel to the plane.
    const double cos_plane = std::abs(glm::dot(q.normal(), d));
    if (cos_plane < 1e-6 || std::abs(static_cast<double>(s.a)) < 1e-6 ||
        std::abs(static_cast<double>(s.a - 1)) < 1e-6 ||
        std::abs(static_cast<double>(s.b)) < 1e-6 || std::abs(static_cast<double>(s.b - 1)) < 1e-6)
      continue;
    ++compared;
    const bool expected = s.a > 0 && s.a < 1 && s.b > 0 && s.b < 1 && s.t > 1e-9L;
    const std::optional<Hit> hit = intersect(q, ray, {});
    ASSERT_EQ(hit.has_value(), expected) << "a " << static_cast<double>(s.a) << " b "
                                         << static_cast<double>(s.b) << " cos " << cos_plane;
    if (!hit) {
      ++misses;
      continue;
    }
    ++hits;
    // t to the round-off of coordinates of size 100 sizes, over the cosine to the plane.
    const double tol = 1e-12 * (100.0 * size + static_cast<double>(s.t)) / cos_plane;
    EXPECT_NEAR(hit->t, static_cast<double>(s.t), tol) << "cos " << cos_plane;
    EXPECT_LE(glm::dot(hit->normal, d), 0.0);
    EXPECT_NEAR(std::abs(glm::dot(hit->normal, q.normal())), 1.0, 1e-12);
  }
  EXPECT_GT(hits, 2000);
  EXPECT_GT(misses, 1000);
  EXPECT_GT(compared, 5000);
}

// A ray spawned off a quad, to either side and at any angle down to cos = 1e-4, never hits
// that quad again (it leaves a plane, so any hit would be its own surface).
TEST(QuadPropertyTest, SpawnedRaysNeverHitTheirOwnSurface) {
  Rng rng(5, 0);
  int spawned_rays = 0;
  for (const Vec3& d : direction_cases(rng, 6000)) {
    const Quad q = random_quad(rng);
    const double size = std::sqrt(q.area());
    const Vec3 target = q.corner() + (0.05 + 0.9 * rng.uniform()) * q.edge_u() +
                        (0.05 + 0.9 * rng.uniform()) * q.edge_v();
    // Incoming rays at any angle to either face, grazing ones included; the case's direction
    // picks the face.
    const double cos_in = random_cos(rng);
    const Vec3 n = glm::dot(d, q.normal()) < 0.0 ? q.normal() : -q.normal();
    const Vec3 incoming = direction_at(-n, cos_in, rng);
    const Ray ray{target - size * incoming, incoming};
    const std::optional<Hit> hit = intersect(q, ray, {});
    if (!hit) continue;  // round-off at a grazing angle can still miss near the edges
    for (const bool reflect : {true, false}) {
      const Vec3 wi = direction_at(reflect ? hit->normal : -hit->normal, random_cos(rng), rng);
      const Ray out = spawn_ray(*hit, wi);
      EXPECT_GT(glm::dot(out.origin - hit->point, hit->normal) * glm::dot(wi, hit->normal), 0.0);
      const auto again = intersect_distance(q, out, {});
      EXPECT_FALSE(again) << "size " << size << " t " << again.value_or(0.0);
      ++spawned_rays;
    }
  }
  EXPECT_GT(spawned_rays, 10000);
}

}  // namespace
