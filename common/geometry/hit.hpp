#pragma once
/// The record of a ray hitting a surface, and the one place that moves new rays off it.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/ray.hpp"

namespace mcrt {

struct Hit {
  double t = 0.0;
  Vec3 point;
  Vec3 normal;  ///< unit, facing the incoming ray (the side the ray arrived from)
  std::uint32_t material = 0;
  /// The ray arrived on the side the surface's own normal points to: a sphere's outside, a
  /// quad's front. A dielectric reads it to know whether the ray enters the glass or leaves it.
  bool front_face = true;
};

/// Geometric normal n turned to face against the ray direction d. A ray exactly tangent to the
/// surface (n.d = 0) meets its front: so it is pushed off outwards and goes on past a sphere,
/// instead of being pushed inside it and meeting the sphere again from within.
inline Vec3 face_forward(const Vec3& n, const Vec3& d) { return glm::dot(n, d) <= 0.0 ? n : -n; }

/// Sets hit.normal to the geometric normal n turned against d (face_forward, the same bits) and
/// hit.front_face to whether n already faced against d.
inline void set_face_normal(Hit& hit, const Vec3& n, const Vec3& d) {
  hit.front_face = glm::dot(n, d) <= 0.0;
  hit.normal = hit.front_face ? n : -n;
}

/// A ray leaving `hit` in `direction`, its origin pushed off the surface along the normal
/// (to the side the direction goes) so it cannot hit the surface it starts on. The offset is
/// relative to the coordinates' size: round-off in the hit point grows with them (the walls of
/// the sphere Cornell box sit 1e5 away from their centres).
inline Ray spawn_ray(const Hit& hit, const Vec3& direction) {
  const double scale =
      1.0 + std::max({std::abs(hit.point.x), std::abs(hit.point.y), std::abs(hit.point.z)});
  const double offset = 1e-7 * scale;
  const double side = glm::dot(direction, hit.normal) >= 0.0 ? 1.0 : -1.0;
  return {hit.point + side * offset * hit.normal, direction};
}

/// Shadow-ray helper: a ray from `hit` towards `target`, with the distance to it. The ray is
/// aimed from its pushed-off origin, so it passes through the target itself: aimed from the
/// hit point instead, it would run parallel to the line to the target, a push-off (1e-5 in
/// the sphere Cornell box) beside it, and meet a light's surface up to that much before the
/// target, which for a light a few units away is more than the 1e-6 the shadow ray is cut
/// short by (the light then hid itself).
struct SegmentRay {
  Ray ray;
  double distance;
};
inline SegmentRay spawn_ray_to(const Hit& hit, const Vec3& target) {
  const Vec3 origin = spawn_ray(hit, target - hit.point).origin;  // the side of the target
  const Vec3 to = target - origin;
  const double distance = glm::length(to);
  return {{origin, to / distance}, distance};
}

}  // namespace mcrt
