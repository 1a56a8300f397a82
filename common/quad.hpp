#pragma once
/// Parallelogram corner + a*edge_u + b*edge_v, a, b in [0, 1], and its ray intersection.

#include <cmath>
#include <cstdint>
#include <optional>

#include "hit.hpp"

namespace mcrt {

struct Quad {
  Vec3 corner;
  Vec3 edge_u;
  Vec3 edge_v;
  std::uint32_t material = 0;

  /// Unit normal cross(edge_u, edge_v) / |...|: the side an area light emits towards.
  Vec3 normal() const { return glm::normalize(glm::cross(edge_u, edge_v)); }
  double area() const { return glm::length(glm::cross(edge_u, edge_v)); }
  Vec3 center() const { return corner + 0.5 * (edge_u + edge_v); }
};

/// Plane hit t = n.(corner - o) / n.d, then the hit's coordinates (a, b) in the edges' basis
/// must lie in [0,1]^2. A ray parallel to the plane (n.d = 0) misses.
inline std::optional<double> intersect_distance(const Quad& q, const Ray& ray, Interval range) {
  const Vec3 n = glm::cross(q.edge_u, q.edge_v);
  const double denom = glm::dot(n, ray.direction);
  if (std::abs(denom) < 1e-12 * glm::length(n)) return std::nullopt;
  const double t = glm::dot(n, q.corner - ray.origin) / denom;
  if (!range.contains(t)) return std::nullopt;
  const Vec3 p = ray.at(t) - q.corner;
  const Vec3 w = n / glm::dot(n, n);
  const double a = glm::dot(w, glm::cross(p, q.edge_v));
  const double b = glm::dot(w, glm::cross(q.edge_u, p));
  if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return std::nullopt;
  return t;
}

/// The hit record at distance t along the ray (t from intersect_distance).
inline Hit hit_at(const Quad& q, const Ray& ray, double t) {
  Hit hit;
  hit.t = t;
  hit.point = ray.at(t);
  hit.normal = face_forward(q.normal(), ray.direction);
  hit.material = q.material;
  return hit;
}

inline std::optional<Hit> intersect(const Quad& q, const Ray& ray, Interval range) {
  if (const std::optional<double> t = intersect_distance(q, ray, range)) return hit_at(q, ray, *t);
  return std::nullopt;
}

}  // namespace mcrt
