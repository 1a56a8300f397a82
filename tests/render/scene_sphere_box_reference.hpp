#pragma once
// An independent reference for smallpt's sphere box, both as `cornell-spheres` (every material
// diffuse) and as `smallpt` (its mirror and glass balls; render/scene.cpp), written
// deliberately differently from the project's renderer so the two share no code on the way
// from a pixel to its radiance:
//  - the scene is re-stated here from smallpt's numbers (nine spheres);
//  - rays meet spheres through the quadratic's stable pair of roots, t0 = q and t1 = c / q with
//    q = -(b + sign(b) sqrt(b^2 - c)) (the project uses b -+ sqrt(b^2 - c));
//  - smallpt's own camera vectors, cx along x and cy = (cx x d) |cy| = 0.5135, with the rays
//    starting 140 units along the normalised pixel direction (as smallpt runs), and a box
//    filter;
//  - cosine-weighted directions in smallpt's basis around the normal (the project uses Duff et
//    al.'s), and Russian roulette with survival max(colour), unbiased for every bounce;
//  - the mirror by d - 2 (n.d) n; the glass as smallpt writes it: the refracted direction from
//    the index ratio and the outward normal, Schlick's reflectance, and the branch chosen with
//    smallpt's probability P = 1/4 + R/2 (weights R / P and T / (1 - P)), not with R itself;
//  - no light sampling: emission is added wherever a path meets the light, from either side.
// The comparison (sphere_box_comparison_p_value) is region by region (support/
// region_comparison.hpp): blocks, rows, columns and the border, so that a bias in a few pixels
// of the top row is seen.

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
#include "support/color_moments.hpp"
#include "support/region_comparison.hpp"

namespace mcrt::testing {

enum class ReferenceSurface { diffuse, mirror, glass };

struct ReferenceSphere {
  double radius;
  Vec3 centre;
  Color albedo, emission;  ///< albedo: the colour smallpt multiplies by, whatever the surface
  ReferenceSurface surface = ReferenceSurface::diffuse;
};

/// smallpt's scene: with `specular`, its mirror and glass balls; without, both white and
/// diffuse (albedo 0.999), as cornell-spheres.
inline std::array<ReferenceSphere, 9> reference_sphere_box(bool specular = false) {
  const Color none(0.0), grey(0.75), white(0.999);
  using enum ReferenceSurface;
  return {{
      {1e5, {1e5 + 1, 40.8, 81.6}, {0.75, 0.25, 0.25}, none},    // left
      {1e5, {-1e5 + 99, 40.8, 81.6}, {0.25, 0.25, 0.75}, none},  // right
      {1e5, {50, 40.8, 1e5}, grey, none},                        // back
      {1e5, {50, 40.8, -1e5 + 170}, none, none},                 // front (black)
      {1e5, {50, 1e5, 81.6}, grey, none},                        // bottom
      {1e5, {50, -1e5 + 81.6, 81.6}, grey, none},                // top
      {16.5, {27, 16.5, 47}, white, none, specular ? mirror : diffuse},
      {16.5, {73, 16.5, 78}, white, none, specular ? glass : diffuse},
      {600, {50, 681.6 - 0.27, 81.6}, none, Color(12.0)},  // the light
  }};
}

/// smallpt's glass (index 1.5 in air): the new direction and the factor on the path's weight
/// for a ray of direction d meeting it at outward normal n; u in [0, 1) picks the branch.
inline Vec3 reference_glass_bounce(const Vec3& d, const Vec3& n, double u, double& factor) {
  const Vec3 mirrored = d - n * (2.0 * glm::dot(n, d));
  const bool into = glm::dot(n, d) < 0.0;
  const Vec3 nl = into ? n : -n;
  const double n_air = 1.0, n_glass = 1.5, ratio = into ? n_air / n_glass : n_glass / n_air;
  const double ddn = glm::dot(d, nl);
  const double cos2t = 1.0 - ratio * ratio * (1.0 - ddn * ddn);
  factor = 1.0;
  if (cos2t < 0.0) return mirrored;  // total internal reflection
  const Vec3 through =
      glm::normalize(d * ratio - n * ((into ? 1.0 : -1.0) * (ddn * ratio + std::sqrt(cos2t))));
  const double a = n_glass - n_air, b = n_glass + n_air, r0 = a * a / (b * b);
  const double c = 1.0 - (into ? -ddn : glm::dot(through, n));
  const double re = r0 + (1.0 - r0) * c * c * c * c * c, tr = 1.0 - re;
  const double p = 0.25 + 0.5 * re;
  if (u < p) {
    factor = re / p;
    return mirrored;
  }
  factor = tr / (1.0 - p);
  return through;
}

/// The nearest root t > eps of |o + t d - c|^2 = r^2 (|d| = 1): t^2 + 2 b t + c = 0 with
/// b = d.(o - c), c = |o - c|^2 - r^2; the roots q and c / q, q = -(b + sign(b) sqrt(b^2 - c)).
inline std::optional<double> reference_sphere_distance(const ReferenceSphere& s, const Vec3& o,
                                                       const Vec3& d) {
  const Vec3 oc = o - s.centre;
  const double b = glm::dot(d, oc), c = glm::dot(oc, oc) - s.radius * s.radius;
  const double disc = b * b - c;
  if (disc < 0.0) return std::nullopt;
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  double t0 = q, t1 = q != 0.0 ? c / q : 0.0;
  if (t0 > t1) std::swap(t0, t1);
  const double eps = 1e-4;  // smallpt's: far above round-off at these coordinates
  if (t0 > eps) return t0;
  if (t1 > eps) return t1;
  return std::nullopt;
}

/// L(o, d) with cosine-weighted bounces, smallpt's mirror and glass, and roulette (survival
/// max(albedo), weight / q).
inline Color reference_sphere_radiance(const std::array<ReferenceSphere, 9>& box, Vec3 o, Vec3 d,
                                       Rng& rng) {
  Color sum(0.0), weight(1.0);
  for (;;) {
    double nearest = 1e30;
    const ReferenceSphere* hit = nullptr;
    for (const ReferenceSphere& s : box)
      if (const std::optional<double> t = reference_sphere_distance(s, o, d); t && *t < nearest) {
        nearest = *t;
        hit = &s;
      }
    if (!hit) break;
    sum += weight * hit->emission;
    const double q = std::max({hit->albedo.x, hit->albedo.y, hit->albedo.z});
    if (rng.uniform() >= q) break;  // q = 0 (the light, the front wall) always ends
    weight *= hit->albedo / q;
    o += nearest * d;
    const Vec3 outward = (o - hit->centre) / hit->radius;
    if (hit->surface == ReferenceSurface::mirror) {
      d = glm::normalize(d - outward * (2.0 * glm::dot(outward, d)));
      continue;
    }
    if (hit->surface == ReferenceSurface::glass) {
      double factor = 1.0;
      d = reference_glass_bounce(d, outward, rng.uniform(), factor);
      weight *= factor;
      continue;
    }
    Vec3 w = outward;
    if (glm::dot(w, d) > 0.0) w = -w;
    // smallpt's basis: u perpendicular to w and to whichever axis is not close to it.
    const Vec3 u =
        glm::normalize(glm::cross(std::abs(w.x) > 0.1 ? Vec3(0, 1, 0) : Vec3(1, 0, 0), w));
    const Vec3 v = glm::cross(w, u);
    const double phi = k_two_pi * rng.uniform(), r2 = rng.uniform(), r = std::sqrt(r2);
    d = glm::normalize(u * (std::cos(phi) * r) + v * (std::sin(phi) * r) + w * std::sqrt(1.0 - r2));
  }
  return sum;
}

struct SphereBoxComparison {
  int width = 32, height = 24;  ///< smallpt's 4:3
  int block = 4;
  int samples = 2000;  ///< per pixel, each renderer
};

/// The project's render of `scene` (cornell-spheres or smallpt; `estimate(scene, ray, rng, count)`)
/// against the reference, by regions (support/region_comparison.hpp). The project's render
/// runs once per sample index s (spp 1), so each pixel value is one sample; the reference
/// draws from streams (2^20 + pixel, s), which the render never uses.
template <class Estimate>
RegionVerdict sphere_box_comparison(const Scene& scene, const SphereBoxComparison& c,
                                    std::uint64_t seed, Estimate&& estimate) {
  // The scene says which: cornell-spheres all diffuse, smallpt with its mirror and glass.
  const std::array<ReferenceSphere, 9> box = reference_sphere_box(scene.name == "smallpt");
  const Camera camera(scene.camera, c.width, c.height);
  // smallpt's camera: d = cx (x / w - 1/2) + cy (1/2 - y / h) + forward, row 0 at the top.
  const Vec3 eye(50, 52, 295.6), forward = glm::normalize(Vec3(0, -0.042612, -1));
  const Vec3 cx(c.width * 0.5135 / c.height, 0, 0);
  const Vec3 cy = glm::normalize(glm::cross(cx, forward)) * 0.5135;
  const PairedMoments m = paired_pixel_moments(
      camera, c.width, c.height, c.samples, seed,
      [&](const Ray& ray, Rng& rng, RayCount& count) { return estimate(scene, ray, rng, count); },
      [&](int x, int y, Rng& rng) {
        const Vec2 u = rng.uniform2();
        const Vec3 d =
            cx * ((x + u.x) / c.width - 0.5) + cy * (0.5 - (y + u.y) / c.height) + forward;
        // smallpt's Ray(cam.o + d*140, d.norm()): norm() normalises d first (g++ evaluates
        // the second argument first), so the ray starts 140 along the unit direction.
        const Vec3 unit = glm::normalize(d);
        return reference_sphere_radiance(box, eye + unit * 140.0, unit, rng);
      });
  return region_agreement(m.ours, m.reference, c.width, c.height, c.block);
}

}  // namespace mcrt::testing
