#pragma once
/// Parallelogram corner + a*edge_u + b*edge_v, a, b in [0, 1], and its ray intersection.

#include <cmath>
#include <cstdint>
#include <optional>

#include "geometry/hit.hpp"

namespace mcrt {

/// A quad keeps, beside its corner and edges, what every ray query needs and no ray changes:
/// the plane normal n = cross(edge_u, edge_v), |n| (its area), the unit normal, and the axes
/// that give a point's edge coordinates by one dot product each. Computing them per query cost
/// a cross product, a length and a division (precomputing them: 1.55x the closest-hit queries
/// per second on `cornell`, bench_path_tracer).
class Quad {
 public:
  Quad(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v, std::uint32_t material = 0)
      : corner_(corner),
        edge_u_(edge_u),
        edge_v_(edge_v),
        material_(material),
        plane_normal_(glm::cross(edge_u, edge_v)),
        area_(glm::length(plane_normal_)),
        normal_(plane_normal_ / area_) {
    // With w = n / |n|^2, p = a u + b v has a = w.(p x v) = p.(v x w), b = w.(u x p) = p.(w x u).
    const Vec3 w = plane_normal_ / glm::dot(plane_normal_, plane_normal_);
    axis_a_ = glm::cross(edge_v, w);
    axis_b_ = glm::cross(w, edge_u);
    plane_offset_ = glm::dot(plane_normal_, corner);
    offset_a_ = glm::dot(axis_a_, corner);
    offset_b_ = glm::dot(axis_b_, corner);
  }

  const Vec3& corner() const { return corner_; }
  const Vec3& edge_u() const { return edge_u_; }
  const Vec3& edge_v() const { return edge_v_; }
  std::uint32_t material() const { return material_; }

  /// cross(edge_u, edge_v), not normalised: its length is the area.
  const Vec3& plane_normal() const { return plane_normal_; }
  /// Unit normal cross(edge_u, edge_v) / |...|: the side an area light emits towards.
  const Vec3& normal() const { return normal_; }
  double area() const { return area_; }
  Vec3 center() const { return corner_ + 0.5 * (edge_u_ + edge_v_); }

  /// Edge coordinate a of a point p given relative to the corner (p = a u + b v in the plane).
  double coordinate_a(const Vec3& p) const { return glm::dot(p, axis_a_); }
  /// Edge coordinate b of a point p given relative to the corner.
  double coordinate_b(const Vec3& p) const { return glm::dot(p, axis_b_); }
  const Vec3& axis_a() const { return axis_a_; }
  const Vec3& axis_b() const { return axis_b_; }
  /// The plane is n.x = plane_offset (n = plane_normal()).
  double plane_offset() const { return plane_offset_; }
  /// A point x's edge coordinates are a = axis_a.x - offset_a and b = axis_b.x - offset_b.
  double offset_a() const { return offset_a_; }
  double offset_b() const { return offset_b_; }
  /// A ray with |n.d| below this is taken as parallel to the plane: it misses.
  double parallel_threshold() const { return 1e-12 * area_; }

 private:
  Vec3 corner_, edge_u_, edge_v_;
  std::uint32_t material_;
  Vec3 plane_normal_;
  double area_;
  Vec3 normal_;
  Vec3 axis_a_, axis_b_;
  double plane_offset_, offset_a_, offset_b_;
};

/// The ray o + t d meets the plane n.x = n.corner at t = (n.corner - n.o) / n.d; a ray parallel
/// to the plane (n.d = 0) misses. The hit's edge coordinates (a, b) must lie in [0,1]^2. They
/// are linear in the point, a(x) = axis_a.x - axis_a.corner, so along the ray
/// a = a(o) + t axis_a.d, and the same for b: no hit point is needed.
///
/// Every quad search (QuadSet) does these operations in this order, so all give the same bits.
/// The form with the hit point, a = axis_a.(o + t d - corner), costs about as many operations,
/// but each waits for t's division, then for the point: a chain the four-lane search could not
/// hide (docs/under-the-hood.md).
inline std::optional<double> intersect_distance(const Quad& q, const Ray& ray, Interval range) {
  const Vec3& n = q.plane_normal();
  const double denom = glm::dot(n, ray.direction);
  if (std::abs(denom) < q.parallel_threshold()) return std::nullopt;
  const double t = (q.plane_offset() - glm::dot(n, ray.origin)) / denom;
  if (!range.contains(t)) return std::nullopt;
  const double a =
      (glm::dot(q.axis_a(), ray.origin) - q.offset_a()) + t * glm::dot(q.axis_a(), ray.direction);
  const double b =
      (glm::dot(q.axis_b(), ray.origin) - q.offset_b()) + t * glm::dot(q.axis_b(), ray.direction);
  if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return std::nullopt;
  return t;
}

/// The hit record at distance t along the ray (t from intersect_distance).
inline Hit hit_at(const Quad& q, const Ray& ray, double t) {
  Hit hit;
  hit.t = t;
  hit.point = ray.at(t);
  set_face_normal(hit, q.normal(), ray.direction);
  hit.material = q.material();
  return hit;
}

inline std::optional<Hit> intersect(const Quad& q, const Ray& ray, Interval range) {
  if (const std::optional<double> t = intersect_distance(q, ray, range)) return hit_at(q, ray, *t);
  return std::nullopt;
}

}  // namespace mcrt
