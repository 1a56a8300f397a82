#pragma once
/// Samplers of plane regions: the square [-1,1]^2 and the unit disk, each beside its pdf
/// (per unit area). Pure functions of u in [0,1)^2.

#include <cmath>

#include "core/cos_sin.hpp"
#include "core/math.hpp"

namespace mcrt {

/// Uniform on the square [-1,1]^2: x = 2u - 1. pdf = 1/4 per unit area.
inline Vec2 sample_uniform_square(Vec2 u) { return 2.0 * u - 1.0; }
inline double uniform_square_pdf() { return 0.25; }

/// A point uniform in area on the unit disk, from u uniform in [0,1)^2; uniform_disk_pdf is
/// its density per unit area.
inline Vec2 sample_uniform_disk(Vec2 u) {
  // ASSIGNMENT a2.4 BEGIN stub: (void)u; NOT_IMPLEMENTED(sample_uniform_disk);
  // r = sqrt(u0) (the area inside radius r grows as r^2), phi = 2 pi u1; pdf 1/pi.
  const double r = std::sqrt(u.x);
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  return {r * circle.x, r * circle.y};
  // ASSIGNMENT a2.4 END
}
// ASSIGNMENT a2.4 BEGIN stub: inline double uniform_disk_pdf() { NOT_IMPLEMENTED(uniform_disk_pdf); }
inline double uniform_disk_pdf() { return k_inv_pi; }
// ASSIGNMENT a2.4 END

}  // namespace mcrt
