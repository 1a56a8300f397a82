#pragma once
/// Uniform directions on the whole unit sphere, beside its pdf per steradian.

#include <algorithm>
#include <cmath>

#include "core/cos_sin.hpp"
#include "core/math.hpp"

namespace mcrt {

/// A unit direction uniform in solid angle on the whole sphere, from u uniform in [0,1)^2;
/// uniform_sphere_pdf is its density per steradian.
inline Vec3 sample_uniform_sphere(Vec2 u) {
  // ASSIGNMENT a2.3 BEGIN stub: (void)u; NOT_IMPLEMENTED(sample_uniform_sphere);
  // z = 1 - 2 u0 (Archimedes: the area of a zone is linear in z), phi = 2 pi u1; pdf 1/(4 pi).
  const double z = 1.0 - 2.0 * u.x;
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  return {r * circle.x, r * circle.y, z};
  // ASSIGNMENT a2.3 END
}
// ASSIGNMENT a2.3 BEGIN stub: inline double uniform_sphere_pdf() { NOT_IMPLEMENTED(uniform_sphere_pdf); }
inline double uniform_sphere_pdf() { return 0.25 * k_inv_pi; }
// ASSIGNMENT a2.3 END

}  // namespace mcrt
