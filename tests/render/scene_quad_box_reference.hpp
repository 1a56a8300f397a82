#pragma once
// An independent reference for the quad Cornell box (`cornell`, render/scene.cpp
// make_cornell_box), written deliberately differently from the project's renderer so that the
// two share no code on the way from a pixel to its radiance:
//  - the scene is re-stated here from the Cornell numbers (walls, lamp, the two turned boxes)
//    as triangles, two per face, with the rotation written as a matrix;
//  - rays meet triangles by Moller-Trumbore (the project intersects parallelograms by plane
//    distance and edge coordinates);
//  - its own pinhole camera, and a box filter: a uniform point of the pixel per sample;
//  - directions are cosine-weighted (pdf cos / pi, so the path weight is multiplied by the
//    albedo alone; the project samples uniformly), and paths end by Russian roulette
//    (survival q = max albedo, weight / q), which is unbiased for the whole infinite series of
//    bounces (the project cuts at a depth);
// and the closed form of the irradiance a uniform polygon light gives a point (Lambert's
// formula), with the parallel-rectangle form factor to check it against.
//
// Procedures shared by tests/render/scene_quad_box_checks.cpp and tests/render/scene_quad_box_reference_test.cpp:
// each returns a p-value.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "stats/hypothesis.hpp"
#include "support/color_moments.hpp"
#include "support/region_comparison.hpp"

namespace mcrt::testing {

// ---------------------------------------------------------------------------------------------
// The scene, re-stated.

struct ReferenceTriangle {
  Vec3 a, e1, e2;  ///< vertices a, a + e1, a + e2
  Color albedo, emission;
};

struct ReferenceQuadBox {
  std::vector<ReferenceTriangle> triangles;
  Vec3 eye;
  double vertical_fov;
  std::array<Vec3, 4> lamp;  ///< the lamp's corners in order around it
  Color lamp_radiance, floor_albedo;
};

/// A planar quad given by its four corners in order: the triangles (p0, p1, p2), (p0, p2, p3).
inline void add_reference_face(ReferenceQuadBox& box, const std::array<Vec3, 4>& p, Color albedo,
                               Color emission) {
  box.triangles.push_back({p[0], p[1] - p[0], p[2] - p[0], albedo, emission});
  box.triangles.push_back({p[0], p[2] - p[0], p[3] - p[0], albedo, emission});
}

/// A box of size (w, h, d) standing on the floor, turned by `degrees` about +y (the rotation
/// matrix R_y, x' = x cos + z sin, z' = -x sin + z cos) about its own corner, which then sits
/// at `at`.
inline void add_reference_box(ReferenceQuadBox& box, Vec3 size, double degrees, Vec3 at,
                              Color albedo) {
  const double angle = degrees * k_pi / 180.0;
  const glm::dmat3 r_y(std::cos(angle), 0.0, -std::sin(angle),  // column 0: image of x
                       0.0, 1.0, 0.0,                           // column 1: image of y
                       std::sin(angle), 0.0, std::cos(angle));  // column 2: image of z
  std::array<Vec3, 8> c;  // corner i has x, y, z bits (i & 1, i & 2, i & 4)
  for (int i = 0; i < 8; ++i)
    c[i] = at + r_y * Vec3((i & 1) ? size.x : 0.0, (i & 2) ? size.y : 0.0, (i & 4) ? size.z : 0.0);
  const Color black(0.0);
  add_reference_face(box, {c[0], c[1], c[3], c[2]}, albedo, black);  // z = 0
  add_reference_face(box, {c[4], c[5], c[7], c[6]}, albedo, black);  // z = d
  add_reference_face(box, {c[0], c[4], c[6], c[2]}, albedo, black);  // x = 0
  add_reference_face(box, {c[1], c[5], c[7], c[3]}, albedo, black);  // x = w
  add_reference_face(box, {c[0], c[1], c[5], c[4]}, albedo, black);  // y = 0
  add_reference_face(box, {c[2], c[3], c[7], c[6]}, albedo, black);  // y = h
}

/// The Cornell box of the Cornell data, 555 units, open at the front (z = 0); the lamp 130 x 105
/// one unit below the ceiling, radiance 15; a tall box 165 x 330 x 165 turned 15 degrees at
/// (265, 0, 295) and a short one 165 x 165 x 165 turned -18 degrees at (130, 0, 65) (as in
/// "Ray Tracing: The Next Week"); the eye at (278, 278, -800) looking along +z, 40 degrees of
/// vertical field of view. The lamp is black (albedo 0) and emits on its lower side only (the
/// side its triangles' normals e1 x e2 face: reference_radiance counts Le when a ray meets a
/// triangle against that normal).
inline ReferenceQuadBox make_reference_quad_box() {
  ReferenceQuadBox box;
  const double l = 555.0;
  const Color red(0.65, 0.05, 0.05), green(0.12, 0.45, 0.15), white(0.73), black(0.0);
  box.lamp_radiance = Color(15.0);
  box.floor_albedo = white;
  add_reference_face(box, {Vec3(l, 0, 0), Vec3(l, l, 0), Vec3(l, l, l), Vec3(l, 0, l)}, red, black);
  add_reference_face(box, {Vec3(0, 0, 0), Vec3(0, l, 0), Vec3(0, l, l), Vec3(0, 0, l)}, green,
                     black);
  add_reference_face(box, {Vec3(0, 0, 0), Vec3(l, 0, 0), Vec3(l, 0, l), Vec3(0, 0, l)}, white,
                     black);  // floor
  add_reference_face(box, {Vec3(0, l, 0), Vec3(l, l, 0), Vec3(l, l, l), Vec3(0, l, l)}, white,
                     black);  // ceiling
  add_reference_face(box, {Vec3(0, 0, l), Vec3(l, 0, l), Vec3(l, l, l), Vec3(0, l, l)}, white,
                     black);  // back wall
  box.lamp = {Vec3(213, l - 1, 227), Vec3(343, l - 1, 227), Vec3(343, l - 1, 332),
              Vec3(213, l - 1, 332)};
  add_reference_face(box, box.lamp, black, box.lamp_radiance);
  add_reference_box(box, {165, 330, 165}, 15.0, {265, 0, 295}, white);
  add_reference_box(box, {165, 165, 165}, -18.0, {130, 0, 65}, white);
  box.eye = Vec3(278, 278, -800);
  box.vertical_fov = 40.0 * k_pi / 180.0;
  return box;
}

// ---------------------------------------------------------------------------------------------
// Rays.

/// Moller-Trumbore: solve o + t d = a + u e1 + v e2 by Cramer's rule with p = d x e2,
/// q = (o - a) x e1: det = e1.p, u = (o - a).p / det, v = d.q / det, t = e2.q / det;
/// a hit needs u, v >= 0, u + v <= 1 and t > t_min.
inline std::optional<double> moller_trumbore(const ReferenceTriangle& tri, const Vec3& o,
                                             const Vec3& d, double t_min) {
  const Vec3 p = glm::cross(d, tri.e2);
  const double det = glm::dot(tri.e1, p);
  if (std::abs(det) < 1e-12) return std::nullopt;  // the ray runs along the triangle's plane
  const double inv_det = 1.0 / det;
  const Vec3 s = o - tri.a;
  const double u = glm::dot(s, p) * inv_det;
  if (u < 0.0 || u > 1.0) return std::nullopt;
  const Vec3 q = glm::cross(s, tri.e1);
  const double v = glm::dot(d, q) * inv_det;
  if (v < 0.0 || u + v > 1.0) return std::nullopt;
  const double t = glm::dot(tri.e2, q) * inv_det;
  if (t <= t_min) return std::nullopt;
  return t;
}

struct ReferenceHit {
  double t;
  std::size_t triangle;
};

/// Hits closer than 1e-6 are the ray's own start point: round-off of coordinates below 1e3 is
/// about 1e-13, and the smallest gap of the scene (lamp to ceiling) is 1.
inline std::optional<ReferenceHit> reference_closest_hit(const ReferenceQuadBox& box, const Vec3& o,
                                                         const Vec3& d) {
  std::optional<ReferenceHit> best;
  for (std::size_t i = 0; i < box.triangles.size(); ++i)
    if (const auto t = moller_trumbore(box.triangles[i], o, d, 1e-6); t && (!best || *t < best->t))
      best = ReferenceHit{*t, i};
  return best;
}

/// The pinhole camera: the view looks along +z with y up, so the image's right is -x. Pixel
/// position (px, py) in [0, w) x [0, h), row 0 at the top, maps to the screen at unit distance:
/// s = (2 px / w - 1) tan(fov / 2) w / h, t = (1 - 2 py / h) tan(fov / 2).
inline Vec3 reference_camera_direction(const ReferenceQuadBox& box, int width, int height,
                                       double px, double py) {
  const double half_height = std::tan(0.5 * box.vertical_fov);
  const double s = (2.0 * px / width - 1.0) * half_height * width / height;
  const double t = (1.0 - 2.0 * py / height) * half_height;
  return glm::normalize(Vec3(-s, t, 1.0));
}

/// Cosine-weighted about the unit normal n: a uniform point of the unit disk (by its radius
/// sqrt(u1) and angle), lifted to the hemisphere, in the basis of Duff et al. around n.
inline Vec3 reference_cosine_direction(const Vec3& n, Rng& rng) {
  const double r = std::sqrt(rng.uniform()), phi = k_two_pi * rng.uniform();
  const double x = r * std::cos(phi), y = r * std::sin(phi),
               z = std::sqrt(std::max(0.0, 1.0 - r * r));
  const double sign = std::copysign(1.0, n.z), a = -1.0 / (sign + n.z), b = n.x * n.y * a;
  const Vec3 t1(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const Vec3 t2(b, sign + n.y * n.y * a, -n.y);
  return glm::normalize(x * t1 + y * t2 + z * n);
}

/// L(o, d) = Le + integral of (rho / pi) L cos: per bounce, a cosine-weighted direction
/// (pdf cos / pi: the weight f_r cos / pdf is rho) and Russian roulette with survival
/// q = max(rho) (weight rho / q, at most 1 per channel). E[sum of weighted Le] is the radiance
/// of all paths, however long.
inline Color reference_radiance(const ReferenceQuadBox& box, Vec3 o, Vec3 d, Rng& rng) {
  Color sum(0.0), weight(1.0);
  for (;;) {
    const std::optional<ReferenceHit> hit = reference_closest_hit(box, o, d);
    if (!hit) break;
    const ReferenceTriangle& tri = box.triangles[hit->triangle];
    if (glm::dot(glm::cross(tri.e1, tri.e2), d) < 0.0) sum += weight * tri.emission;  // one-sided
    const double q = std::max({tri.albedo.x, tri.albedo.y, tri.albedo.z});
    if (rng.uniform() >= q) break;  // q = 0 (the lamp) always ends: its albedo is 0
    weight *= tri.albedo / q;
    o += hit->t * d;
    Vec3 n = glm::normalize(glm::cross(tri.e1, tri.e2));
    if (glm::dot(n, d) > 0.0) n = -n;
    d = reference_cosine_direction(n, rng);
  }
  return sum;
}

/// The same radiance by next-event estimation, for comparing the project's NEE and MIS with a
/// reference of about their noise (the path-traced one finds the lamp by luck: its region means
/// are so skewed that z-tests against it reject too often, measured by the calibration): Le of
/// the camera ray's hit, then at every vertex a uniform point y of the lamp (the parallelogram
/// of its corners, pdf 1 / A) whose light, if the segment to it is clear, adds
///   weight (rho / pi) Le cos(theta_x) cos(theta_y) A / r^2,
/// and a cosine-weighted bounce whose hit on the lamp adds nothing (the light sample counted
/// it). Roulette as reference_radiance; the lamp's albedo 0 ends a path that meets it.
inline Color reference_radiance_nee(const ReferenceQuadBox& box, Vec3 o, Vec3 d, Rng& rng) {
  const Vec3 lamp_u = box.lamp[1] - box.lamp[0], lamp_v = box.lamp[3] - box.lamp[0];
  const Vec3 lamp_cross = glm::cross(lamp_u, lamp_v);
  const double lamp_area = glm::length(lamp_cross);
  const Vec3 lamp_normal = lamp_cross / lamp_area;  // (0, -1, 0): the side it emits to
  Color sum(0.0), weight(1.0);
  for (bool first = true;; first = false) {
    const std::optional<ReferenceHit> hit = reference_closest_hit(box, o, d);
    if (!hit) break;
    const ReferenceTriangle& tri = box.triangles[hit->triangle];
    if (first && glm::dot(glm::cross(tri.e1, tri.e2), d) < 0.0) sum += weight * tri.emission;
    const double q = std::max({tri.albedo.x, tri.albedo.y, tri.albedo.z});
    if (rng.uniform() >= q) break;
    weight *= tri.albedo / q;
    o += hit->t * d;
    Vec3 n = glm::normalize(glm::cross(tri.e1, tri.e2));
    if (glm::dot(n, d) > 0.0) n = -n;
    // The light sample: y uniform on the lamp, the segment o -> y clear up to just before y.
    const Vec3 y = box.lamp[0] + rng.uniform() * lamp_u + rng.uniform() * lamp_v;
    const Vec3 to_light = y - o;
    const double r2 = glm::dot(to_light, to_light), r = std::sqrt(r2);
    const Vec3 w = to_light / r;
    const double cos_x = glm::dot(n, w), cos_y = -glm::dot(lamp_normal, w);
    if (cos_x > 0.0 && cos_y > 0.0) {
      const std::optional<ReferenceHit> blocker = reference_closest_hit(box, o, w);
      if (!blocker || blocker->t > r * (1.0 - 1e-6))
        sum += weight * (k_inv_pi * cos_x * cos_y * lamp_area / r2) * box.lamp_radiance;
    }
    d = reference_cosine_direction(n, rng);  // the bounce
  }
  return sum;
}

// ---------------------------------------------------------------------------------------------
// The irradiance of a polygon light.

/// Lambert's formula: a polygon of uniform radiance Le seen from x with unit normal n gives
/// E = Le / 2 |sum over edges i of Theta_i (n . gamma_i)|, Theta_i the angle the edge
/// (v_i, v_i+1) subtends at x and gamma_i the unit normal of the plane through x and the edge.
/// (The polygon must lie wholly above x's tangent plane, unoccluded.)
inline double polygon_irradiance(const Vec3& x, const Vec3& n, const std::array<Vec3, 4>& v,
                                 double le) {
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 a = glm::normalize(v[i] - x), b = glm::normalize(v[(i + 1) % v.size()] - x);
    const double theta = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    sum += theta * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * le * std::abs(sum);
}

/// The form factor from a small patch to a parallel a x b rectangle at height c, the patch
/// under one corner: F = 1/(2 pi) [A / sqrt(1 + A^2) atan(B / sqrt(1 + A^2)) + (A <-> B)],
/// A = a / c, B = b / c; the irradiance is E = pi Le F.
inline double corner_rectangle_form_factor(double a, double b, double c) {
  const double big_a = a / c, big_b = b / c;
  const double sa = std::sqrt(1.0 + big_a * big_a), sb = std::sqrt(1.0 + big_b * big_b);
  return (big_a / sa * std::atan(big_b / sa) + big_b / sb * std::atan(big_a / sb)) / k_two_pi;
}

// ---------------------------------------------------------------------------------------------
// The procedures.

struct QuadBoxComparison {
  int width = 16, height = 12;  ///< image size
  int block = 4;                ///< blocks of block x block pixels
  int samples = 2000;           ///< samples per pixel, each renderer
  int depth = 50;               ///< the project's path depth
  bool nee_reference = false;   ///< the reference by reference_radiance_nee, not path tracing
};

/// The project's render of `scene` (render/render.hpp, `estimate(scene, ray, depth, rng,
/// count)` per sample) against the reference, by blocks, rows, columns and the image's border
/// (support/region_comparison.hpp). Both estimate each region's mean
/// radiance: the mean over its pixels of the pixel's mean over its area (box filter). The
/// project's render is run once per sample index s (spp 1, first_sample s), so every pixel
/// value is one sample and its spread is measured; the reference draws from streams
/// (2^20 + pixel, s), which the render (streams (pixel, s)) never uses. The z-tests and their
/// Sidak combination are region_comparison.hpp's (false-failure rate at most alpha).
template <class Estimate>
double quad_box_comparison_p_value(const Scene& scene, const QuadBoxComparison& c,
                                   std::uint64_t seed, Estimate&& estimate) {
  const ReferenceQuadBox box = make_reference_quad_box();
  const Camera camera(scene.camera, c.width, c.height);
  const PairedMoments m = paired_pixel_moments(
      camera, c.width, c.height, c.samples, seed,
      [&](const Ray& ray, Rng& rng, RayCount& count) {
        return estimate(scene, ray, c.depth, rng, count);
      },
      [&](int x, int y, Rng& rng) {
        const Vec2 u = rng.uniform2();  // the box filter: a uniform point of the pixel
        const Vec3 d = reference_camera_direction(box, c.width, c.height, x + u.x, y + u.y);
        return c.nee_reference ? reference_radiance_nee(box, box.eye, d, rng)
                               : reference_radiance(box, box.eye, d, rng);
      });
  return region_agreement(m.ours, m.reference, c.width, c.height, c.block).p_value;
}

/// Floor points where the lamp's direct light is known in closed form; `whole_box` says
/// whether the point sees the whole lamp in the full scene (else only in the room without its
/// two boxes).
struct FloorPoint {
  Vec3 x;
  bool whole_box;
};

/// The project's direct light at floor points: a ray straight down onto x and
/// estimate(scene, ray, 1, ...) (depth 1: the floor's emission, 0, plus one bounce) estimates
/// L = (rho / pi) E(x), E from polygon_irradiance with the reference's lamp. One z-test per
/// point and channel-sum (the floor is white and the lamp grey, so every channel carries the
/// same samples), n paths each, Sidak over the points. `room` is `cornell` without its two
/// boxes, `whole` the full scene.
template <class Estimate>
double direct_light_p_value(const Scene& room, const Scene& whole,
                            const std::vector<FloorPoint>& points, int n, std::uint64_t seed,
                            Estimate&& estimate) {
  const ReferenceQuadBox box = make_reference_quad_box();
  std::vector<double> p_values;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Scene& scene = points[i].whole_box ? whole : room;
    const Ray down{points[i].x + Vec3(0, 10, 0), Vec3(0, -1, 0)};
    double sum = 0.0, sum2 = 0.0;
    RayCount count;
    for (int k = 0; k < n; ++k) {
      Rng rng(seed, stream_index((std::uint64_t{1} << 21) + i, static_cast<std::uint64_t>(k)));
      const Color l = estimate(scene, down, 1, rng, count);
      const double v = l.x + l.y + l.z;
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / n, variance = (sum2 - sum * mean) / (n - 1.0);
    const double e = polygon_irradiance(points[i].x, Vec3(0, 1, 0), box.lamp, box.lamp_radiance.x);
    const double expected =
        (box.floor_albedo.x + box.floor_albedo.y + box.floor_albedo.z) * k_inv_pi * e;
    p_values.push_back(z_test_p_value(mean, expected, std::sqrt(variance / n)));
  }
  return sidak_p_value(p_values);
}

/// `cornell` without its two boxes: its walls (the quads as large as a wall) and its one-sided
/// lamp.
inline Scene cornell_room_without_boxes() {
  const Scene whole = make_cornell_box();
  Scene room;
  room.materials = whole.materials;
  room.camera = whole.camera;
  const double wall_area = 555.0 * 555.0;
  for (std::size_t i = 0; i < whole.quads().size(); ++i) {
    const Quad& q = whole.quads()[i];
    if (whole.materials[q.material()].is_emitter())
      room.add_quad(q, whole.quad_face_material(i, q.normal()));  // with its black back
    else if (q.area() >= 0.999 * wall_area)
      room.add_quad(q);
  }
  return room;
}

/// Floor points: under the lamp's centre, under a corner, to one side (in the room), and one
/// in front by the red wall that sees the whole lamp past both boxes (the nearest miss: the
/// ray to the lamp's far corner passes the tall box's front face about 19 units in front of
/// it at the box's top height).
inline std::vector<FloorPoint> direct_light_points() {
  return {{Vec3(278, 0, 279.5), false},
          {Vec3(213, 0, 227), false},
          {Vec3(100, 0, 450), false},
          {Vec3(500, 0, 100), true}};
}

}  // namespace mcrt::testing
