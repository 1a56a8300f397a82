#pragma once
// Known-wrong samplers and pdfs, kept so the tests can show the chi-square sampler test
// (stats/sampler_tests.hpp) rejects them (tests/stats/known_bugs_test.cpp).

#include <algorithm>
#include <cmath>

#include "core/math.hpp"
#include "sampling/frame.hpp"
#include "sampling/phong.hpp"

namespace mcrt::testing {

/// Wrong: r = u instead of sqrt(u), so points crowd the disk's centre.
inline Vec2 disk_with_radius_u(Vec2 u) {
  const double r = u.x;
  const double phi = k_two_pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi)};
}

/// Wrong: the cosine-weighted hemisphere by Malley's method with the disk point at r = u0
/// instead of sqrt(u0): cos(theta) = sqrt(1 - u0^2) has density z / sqrt(1 - z^2) instead of
/// 2z, half the expected samples at the horizon and ever more towards the pole.
inline Vec3 cosine_hemisphere_with_radius_u(Vec2 u) {
  const Vec2 d = disk_with_radius_u(u);
  return {d.x, d.y, std::sqrt(std::max(0.0, 1.0 - d.x * d.x - d.y * d.y))};
}

/// Wrong: the uniform hemisphere's pdf given as 1/pi instead of 1/(2 pi) per steradian.
inline double hemisphere_pdf_one_over_pi(const Vec3&) { return k_inv_pi; }

/// Wrong: the cosine-weighted pdf with an extra factor 2, 2 cos(theta) / pi.
inline double cosine_pdf_times_two(const Vec3& w) { return 2.0 * w.z * k_inv_pi; }

/// Wrong: the Phong lobe's pdf normalised with the BRDF's m + 2 instead of m + 1, so it claims
/// (m + 2)/(m + 1) times the probability of every direction (10 % more at m = 10).
inline double phong_lobe_pdf_with_m_plus_2(const Vec3& wi, const Vec3& reflected, double m) {
  return (m + 2.0) / (m + 1.0) * phong_lobe_pdf(wi, reflected, m);
}

/// Wrong: cos(alpha) = u0^(1/m) instead of u0^(1/(m + 1)): the density of cos(alpha) is
/// m c^(m - 1), the inversion of the lobe without the solid angle's d(cos alpha) counted
/// (uniform on the hemisphere at m = 1). Its t = c^(m + 1) = u0^(1 + 1/m), so it shrinks out of
/// sight as m grows: visible at m = 10, not at m = 1000 with 1e5 samples.
inline Vec3 sample_phong_lobe_cos_u_to_one_over_m(Vec2 u, const Vec3& reflected, double m) {
  const double cos_alpha = std::pow(u.x, 1.0 / m);
  const double sin_alpha = std::sqrt(std::max(0.0, 1.0 - cos_alpha * cos_alpha));
  const double phi = k_two_pi * u.y;
  return Frame(reflected).to_world(
      {sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha});
}

/// Wrong: the diffuse + lobe pdf mixed half and half, whatever rho_s / (rho_s + rho_d) the
/// sampler chooses the lobe with.
inline double phong_pdf_mixed_half_and_half(const Phong& material, const Vec3& wi, const Vec3& n,
                                            const Vec3& wo) {
  return 0.5 * phong_lobe_pdf(wi, mirror_direction(wo, n), material.m) +
         0.5 * std::max(0.0, glm::dot(wi, n)) * k_inv_pi;
}

/// Wrong: the hemisphere sampled uniform in angle, theta = pi/2 u0: the density per steradian
/// is 1 / (pi^2 sin(theta)), 2 / (pi sin(theta)) times the uniform one: too few directions near
/// the horizon, ever more towards the pole.
inline Vec3 hemisphere_uniform_in_angle(Vec2 u) {
  const double theta = 0.5 * k_pi * u.x, phi = k_two_pi * u.y;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

/// Wrong: the sphere sampled uniform in angle, theta = pi u0: 2 / (pi sin(theta)) times the
/// uniform density, crowding both poles.
inline Vec3 sphere_uniform_in_angle(Vec2 u) {
  const double theta = k_pi * u.x, phi = k_two_pi * u.y;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

/// Wrong: the cone sampled with cos(theta) = u0 cos(theta_max), which runs from 0 to
/// cos(theta_max): every direction lies outside the cone (between it and the horizon).
inline Vec3 cone_with_cos_u_times_max(Vec2 u, double cos_theta_max) {
  const double z = u.x * cos_theta_max, s = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = k_two_pi * u.y;
  return {s * std::cos(phi), s * std::sin(phi), z};
}

/// Wrong: the cone sampled uniform in angle, theta = u0 theta_max: the density per steradian
/// goes as 1 / sin(theta), ever more directions towards the axis.
inline Vec3 cone_uniform_in_angle(Vec2 u, double cos_theta_max) {
  const double theta = u.x * std::acos(cos_theta_max), phi = k_two_pi * u.y;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

/// Wrong: the cone's pdf without the 2 pi of the turn in phi, 1 / (1 - cos(theta_max)).
inline double cone_pdf_without_two_pi(double cos_theta, double cos_theta_max) {
  return cos_theta < cos_theta_max ? 0.0 : 1.0 / (1.0 - cos_theta_max);
}

}  // namespace mcrt::testing
