#pragma once
/// Sphere |p - c| = r and its ray intersection.

#include <cmath>
#include <cstdint>
#include <optional>

#include "geometry/hit.hpp"

namespace mcrt {

struct Sphere {
  Vec3 center;
  double radius = 1.0;
  std::uint32_t material = 0;
};

/// Nearest t in `range` with |o + t d - c| = r, |d| = 1:
/// t^2 - 2 b t + c = 0 with b = d.(c - o), c = |c - o|^2 - r^2, so t = b -+ sqrt(b^2 - c).
/// Written with b = d.(c - o) as smallpt does: stable for the 1e5-radius walls.
inline std::optional<double> intersect_distance(const Sphere& s, const Ray& ray, Interval range) {
  const Vec3 oc = s.center - ray.origin;
  const double b = glm::dot(oc, ray.direction);
  const double det = b * b - glm::dot(oc, oc) + s.radius * s.radius;
  if (det < 0.0) return std::nullopt;
  const double root = std::sqrt(det);
  if (range.contains(b - root)) return b - root;
  if (range.contains(b + root)) return b + root;
  return std::nullopt;
}

/// The hit record at distance t along the ray (t from intersect_distance), with the sphere's
/// 1/r given, so the normal (p - c) / r costs three products. Scene keeps 1/r per sphere, so a
/// bounce does not wait for a division after the search.
inline Hit hit_at(const Sphere& s, const Ray& ray, double t, double inverse_radius) {
  Hit hit;
  hit.t = t;
  hit.point = ray.at(t);
  set_face_normal(hit, (hit.point - s.center) * inverse_radius, ray.direction);
  hit.material = s.material;
  return hit;
}

/// The same, dividing once here: one division and three products, not three divisions.
inline Hit hit_at(const Sphere& s, const Ray& ray, double t) {
  return hit_at(s, ray, t, 1.0 / s.radius);
}

inline std::optional<Hit> intersect(const Sphere& s, const Ray& ray, Interval range) {
  if (const std::optional<double> t = intersect_distance(s, ray, range)) return hit_at(s, ray, *t);
  return std::nullopt;
}

}  // namespace mcrt
