#pragma once
/// Directions uniform in a cone round +z, beside its pdf per steradian: the directions from a
/// point that meet a sphere light (half-angle theta_max with sin(theta_max) = R / d): a2.5, a
/// sampler the student derives from its pdf by inversion.

#include <algorithm>
#include <cmath>

#include "core/cos_sin.hpp"
#include "core/math.hpp"

namespace mcrt {

/// Uniform in solid angle over the cone cos(theta) >= cos_theta_max round +z. The cone's cap of
/// directions has solid angle 2 pi (1 - cos(theta_max)), so
///   p(w) = 1 / (2 pi (1 - cos(theta_max))).
inline Vec3 sample_uniform_cone(Vec2 u, double cos_theta_max) {
  // ASSIGNMENT a2.5 BEGIN stub: (void)u; (void)cos_theta_max; NOT_IMPLEMENTED(sample_uniform_cone);
  // The inversion (inside the region: a kit asks for it). d omega = d phi d cos(theta), so cos(theta)
  // is uniform on [cos(theta_max), 1], its cdf F = (1 - cos(theta)) / (1 - cos(theta_max)),
  // inverted at u0: cos(theta) = 1 - u0 (1 - cos(theta_max)); phi = 2 pi u1 independently.
  // (1 - u0 is uniform too: cos(theta) = cos(theta_max) + u0 (1 - cos(theta_max)) is as good.)
  const double cos_theta = 1.0 - u.x * (1.0 - cos_theta_max);
  // 1 - cos^2 as (1 - cos)(1 + cos): a narrow cone (cos near 1) keeps the digits of sin
  const double sin_theta = std::sqrt(std::max(0.0, (1.0 - cos_theta) * (1.0 + cos_theta)));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  return {sin_theta * circle.x, sin_theta * circle.y, cos_theta};
  // ASSIGNMENT a2.5 END
}

/// The pdf of sample_uniform_cone per steradian at a direction with this cos(theta): constant
/// inside the cone, 0 outside it.
inline double uniform_cone_pdf(double cos_theta, double cos_theta_max) {
  // ASSIGNMENT a2.5 BEGIN stub: (void)cos_theta; (void)cos_theta_max; NOT_IMPLEMENTED(uniform_cone_pdf);
  if (cos_theta < cos_theta_max) return 0.0;
  return 1.0 / (k_two_pi * (1.0 - cos_theta_max));
  // ASSIGNMENT a2.5 END
}

}  // namespace mcrt
