#pragma once
/// Samplers of directions on the hemisphere z >= 0 (the local frame, normal = +z), each
/// beside its pdf per steradian. sampling/frame.hpp turns them into world directions.

#include <algorithm>
#include <cmath>

#include "core/math.hpp"
#include "sampling/plane.hpp"

namespace mcrt {

/// Uniform on the hemisphere z >= 0: cos(theta) = u0 (the area of a zone is linear in z),
/// phi = 2 pi u1. pdf = 1/(2 pi) per steradian.
inline Vec3 sample_uniform_hemisphere(Vec2 u) {
  const double cos_theta = u.x;
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const double phi = k_two_pi * u.y;
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}
inline double uniform_hemisphere_pdf() { return k_inv_two_pi; }

/// Cosine-weighted hemisphere (Malley's method: a uniform disk point lifted to the
/// hemisphere). pdf = cos(theta)/pi per steradian.
inline Vec3 sample_cosine_hemisphere(Vec2 u) {
  const Vec2 d = sample_uniform_disk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}
inline double cosine_hemisphere_pdf(double cos_theta) { return cos_theta * k_inv_pi; }

}  // namespace mcrt
