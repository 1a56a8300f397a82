#pragma once
/// Samplers: pure functions of uniform numbers u in [0,1)^2, each beside its pdf.
///
/// They never take a generator, so tests can feed them fixed inputs. Hemisphere samplers
/// return directions in the local frame where the normal is +z; `Frame` rotates them.

#include <algorithm>
#include <cmath>

#include "core/math.hpp"
#include "sampling/unit_circle.hpp"

namespace mcrt {

/// Uniform on the square [-1,1]^2: x = 2u - 1. pdf = 1/4 per unit area.
inline Vec2 sample_uniform_square(Vec2 u) { return 2.0 * u - 1.0; }
inline double uniform_square_pdf() { return 0.25; }

/// Uniform on the unit disk: r = sqrt(u0) (the area inside radius r grows as r^2),
/// phi = 2 pi u1. pdf = 1/pi per unit area.
inline Vec2 sample_uniform_disk(Vec2 u) {
  const double r = std::sqrt(u.x);
  return r * unit_circle_point(u.y);  // (cos phi, sin phi)
}
inline double uniform_disk_pdf() { return k_inv_pi; }

/// Uniform on the hemisphere z >= 0: cos(theta) = u0 (the area of a zone is linear in z),
/// phi = 2 pi u1. pdf = 1/(2 pi) per steradian.
inline Vec3 sample_uniform_hemisphere(Vec2 u) {
  const double cos_theta = u.x;
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const Vec2 phi = unit_circle_point(u.y);  // (cos phi, sin phi)
  return {sin_theta * phi.x, sin_theta * phi.y, cos_theta};
}
inline double uniform_hemisphere_pdf() { return k_inv_two_pi; }

/// Cosine-weighted hemisphere (Malley's method: a uniform disk point lifted to the
/// hemisphere). pdf = cos(theta)/pi per steradian.
inline Vec3 sample_cosine_hemisphere(Vec2 u) {
  const Vec2 d = sample_uniform_disk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}
inline double cosine_hemisphere_pdf(double cos_theta) { return cos_theta * k_inv_pi; }

/// An orthonormal basis around a unit normal n (Duff et al. 2017, branchless).
struct Frame {
  Vec3 tangent, bitangent, normal;

  explicit Frame(const Vec3& n) : normal(n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    tangent = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
  }

  /// Local (x, y, z) with z along the normal -> world direction.
  Vec3 to_world(const Vec3& local) const {
    return local.x * tangent + local.y * bitangent + local.z * normal;
  }
};

}  // namespace mcrt
