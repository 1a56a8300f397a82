#pragma once
/// Samplers of directions on the hemisphere z >= 0 (the local frame, normal = +z), each
/// beside its pdf per steradian. sampling/frame.hpp turns them into world directions.

#include <algorithm>
#include <cmath>

#include "core/cos_sin.hpp"
#include "core/math.hpp"
#include "sampling/plane.hpp"

namespace mcrt {

/// A unit direction uniform in solid angle on the hemisphere z >= 0, from u uniform in [0,1)^2;
/// uniform_hemisphere_pdf is its density per steradian.
inline Vec3 sample_uniform_hemisphere(Vec2 u) {
  // ASSIGNMENT a2.1 BEGIN stub: (void)u; NOT_IMPLEMENTED(sample_uniform_hemisphere);
  // cos(theta) = u0 (the area of a zone is linear in z), phi = 2 pi u1; pdf 1/(2 pi).
  const double cos_theta = u.x;
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  return {sin_theta * circle.x, sin_theta * circle.y, cos_theta};
  // ASSIGNMENT a2.1 END
}
// ASSIGNMENT a2.1 BEGIN stub: inline double uniform_hemisphere_pdf() { NOT_IMPLEMENTED(uniform_hemisphere_pdf); }
inline double uniform_hemisphere_pdf() { return k_inv_two_pi; }
// ASSIGNMENT a2.1 END

/// A unit direction on the hemisphere z >= 0 with density proportional to cos(theta) per
/// steradian, from u uniform in [0,1)^2; cosine_hemisphere_pdf(cos_theta) is that density.
inline Vec3 sample_cosine_hemisphere(Vec2 u) {
  // ASSIGNMENT a2.2 BEGIN stub: (void)u; NOT_IMPLEMENTED(sample_cosine_hemisphere);
  // Malley's method: a uniform disk point lifted to the hemisphere; pdf cos(theta)/pi.
  const Vec2 d = sample_uniform_disk(u);
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
  // ASSIGNMENT a2.2 END
}
// ASSIGNMENT a2.2 BEGIN stub: inline double cosine_hemisphere_pdf(double) { NOT_IMPLEMENTED(cosine_hemisphere_pdf); }
inline double cosine_hemisphere_pdf(double cos_theta) { return cos_theta * k_inv_pi; }
// ASSIGNMENT a2.2 END

}  // namespace mcrt
