#pragma once
/// A glossy material: the normalised modified Phong BRDF (Lafortune & Willems 1994), a lobe
/// round the mirror direction plus an optional diffuse part, with its sampler and pdfs.
/// Pure functions of u in [0,1)^2, doubles, world-space unit vectors.
///
/// The BRDF. wo points away from the surface (towards the eye), n is the unit normal and
///   r = 2 (n . wo) n - wo      the mirror direction of wo about n,
///   cos(alpha) = wi . r        alpha the angle between wi and r,
///   f(wi, wo) = rho_d / pi + rho_s (m + 2) / (2 pi) max(0, cos alpha)^m,
/// with rho_d + rho_s <= 1 and m >= 1 (1 is very rough, 10^4 nearly a mirror). f = 0 when wi
/// or wo is below the surface (wi . n <= 0 or wo . n <= 0): a renderer passes Hit::normal,
/// which faces the incoming ray (geometry/hit.hpp), so wo is above it.
///
/// The lobe's pdf, per steradian, in a frame round r (alpha the polar angle, phi round r):
///   p(wi) = (m + 1) / (2 pi) cos^m(alpha)  for cos alpha > 0, else 0,
/// normalised because dw = d(cos alpha) dphi and the integral of cos^m(alpha) over the
/// hemisphere round r is 2 pi / (m + 1). (The BRDF has m + 2, not m + 1: the extra cos(theta_i)
/// of the rendering equation, so that a white lobe at normal incidence reflects exactly 1.)
///
/// The inversion: sample_phong_lobe_local says how (inside it: it is assignment a6.1).
///
/// The frame round r. (sin alpha cos phi, sin alpha sin phi, cos alpha) is a direction with r
/// as its +z axis; Frame(r) (sampling/frame.hpp) turns it into the world direction.
///
/// Below the surface. The lobe is a cone of directions round r, and when r is not the normal
/// part of that cone is below the surface (all of half of it at grazing incidence). The sampler
/// returns those directions as they are, with their pdf: f = 0 there, so a renderer drops the
/// sample (its contribution is 0, not re-drawn: re-drawing would change the pdf) and counts the
/// loss. That loss is why a white lobe reflects less than 1 away from normal incidence.
///
/// The full material mixes the two parts: choose the lobe with probability
/// P_s = rho_s / (rho_s + rho_d), else a cosine-weighted direction round n, so
///   p(wi) = P_s p_lobe(wi) + (1 - P_s) max(0, wi . n) / pi.
///
/// The estimator each sampler serves: the directional albedo a(wo) = int f(wi, wo) cos(theta_i)
/// dwi, the reflected radiance under uniform incident light of radiance 1, estimated from one
/// direction wi ~ p as Y = f cos(theta_i) / p. For the lobe alone (rho_d = 0),
///   Y = rho_s (m + 2) / (m + 1) max(0, cos theta_i),   so 0 <= Y <= rho_s (m + 2) / (m + 1).
///   E[Y] = a(wo). At normal incidence (r = n, cos theta_i = c): E[c] = (m + 1) / (m + 2) and
///   E[c^2] = (m + 1) / (m + 3), so a = rho_s and Var[Y] = rho_s^2 / ((m + 1) (m + 3)).
///   Elsewhere a(wo) < rho_s (two clamped cosine lobes overlap most when their axes agree:
///   the rearrangement inequality on the sphere), and a bounded Y has
///   Var[Y] <= E[Y] (Y_max - E[Y]) (from Y^2 <= Y_max Y).

#include <algorithm>
#include <cmath>

#include "core/cos_sin.hpp"
#include "core/math.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt {

/// The parameters of a glossy surface.
struct Phong {
  double rho_d = 0.0;  ///< diffuse reflectance, rho_d + rho_s <= 1
  double rho_s = 1.0;  ///< reflectance of the glossy lobe at normal incidence
  double m = 10.0;     ///< Phong exponent in [1, 1e4]: 1 rough, 1e4 nearly a mirror
};

/// r = 2 (n . wo) n - wo: wo reflected about the unit normal n.
inline Vec3 mirror_direction(const Vec3& wo, const Vec3& n) {
  return 2.0 * glm::dot(n, wo) * n - wo;
}

/// cos(alpha) = wi . r(wo) = 2 (n . wi)(n . wo) - wi . wo, written so that swapping wi and wo
/// gives the same floating-point operations in the same order (products commute exactly in
/// IEEE arithmetic): the BRDF is then reciprocal to the last bit, not only up to rounding.
inline double phong_cos_alpha(const Vec3& wi, const Vec3& wo, const Vec3& n) {
  return 2.0 * (glm::dot(n, wi) * glm::dot(n, wo)) - glm::dot(wi, wo);
}

/// max(0, c)^m, 0 below the lobe's horizon. pow underflows to 0 (not NaN) for tiny c at large
/// m; near c = 1 its relative error is about m times that of c (2e-12 at m = 1e4).
inline double phong_cos_power(double cos_alpha, double m) {
  return cos_alpha > 0.0 ? std::pow(std::min(cos_alpha, 1.0), m) : 0.0;
}

/// f(wi, wo) = rho_d / pi + rho_s (m + 2) / (2 pi) max(0, cos alpha)^m for wi and wo above the
/// surface (n . w > 0), else 0.
inline double phong_brdf(const Phong& material, const Vec3& wi, const Vec3& wo, const Vec3& n) {
  if (!(glm::dot(n, wi) > 0.0 && glm::dot(n, wo) > 0.0)) return 0.0;
  const double lobe =
      (material.m + 2.0) * k_inv_two_pi * phong_cos_power(phong_cos_alpha(wi, wo, n), material.m);
  return material.rho_d * k_inv_pi + material.rho_s * lobe;
}

/// A direction round +z (the lobe's frame: z along r) with pdf (m + 1)/(2 pi) cos^m(alpha),
/// sin(alpha) accurate up to m = 1e4.
inline Vec3 sample_phong_lobe_local(Vec2 u, double m) {
  // ASSIGNMENT a6.1 BEGIN stub: (void)u; (void)m; NOT_IMPLEMENTED(sample_phong_lobe_local);
  // The inversion. phi is uniform on [0, 2 pi): phi = 2 pi u1. c = cos(alpha) has density
  // (m + 1) c^m on [0, 1], so its CDF is F(c) = c^(m + 1) and F(c) = u0 gives
  //   c = u0^(1 / (m + 1)) = exp(log(u0) / (m + 1)).
  // For large m, c is within ~1/m of 1, and sin(alpha) = sqrt(1 - c^2) would lose most of its
  // digits to cancellation (at m = 10^4 and u0 near 1, 1 - c^2 ~ 1e-14 and the round-off of c^2
  // is 1e-16: a 1 % error). So 1 - c = -expm1(log(u0) / (m + 1)), computed without
  // cancellation, and sin(alpha) = sqrt((1 - c)(1 + c)).
  const double log_cos_alpha = std::log(u.x) / (m + 1.0);  // u0 = 0: -inf, the lobe's horizon
  const double cos_alpha = std::exp(log_cos_alpha);
  const double one_minus_cos = -std::expm1(log_cos_alpha);
  const double sin_alpha = std::sqrt(one_minus_cos * (1.0 + cos_alpha));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  return {sin_alpha * circle.x, sin_alpha * circle.y, cos_alpha};
  // ASSIGNMENT a6.1 END
}

/// A world direction from the lobe round the unit mirror direction `reflected`. It may be
/// below the surface: see the header (f = 0 there, the renderer drops it).
inline Vec3 sample_phong_lobe(Vec2 u, const Vec3& reflected, double m) {
  return Frame(reflected).to_world(sample_phong_lobe_local(u, m));
}

/// p(wi) = (m + 1)/(2 pi) max(0, wi . r)^m per steradian, over the whole sphere of directions
/// (wi below the surface included: the sampler draws those too).
inline double phong_lobe_pdf(const Vec3& wi, const Vec3& reflected, double m) {
  // ASSIGNMENT a6.1 BEGIN stub: (void)wi; (void)reflected; (void)m; NOT_IMPLEMENTED(phong_lobe_pdf);
  return (m + 1.0) * k_inv_two_pi * phong_cos_power(glm::dot(wi, reflected), m);
  // ASSIGNMENT a6.1 END
}

/// P_s = rho_s / (rho_s + rho_d), the probability of sampling the lobe; 0 for a black surface
/// (any pdf will do where f = 0: the cosine one).
inline double phong_lobe_probability(const Phong& material) {
  const double total = material.rho_s + material.rho_d;
  return total > 0.0 ? material.rho_s / total : 0.0;
}

/// A world direction from the full material at a point with unit normal n, seen from wo:
/// the lobe with probability P_s, else cosine-weighted round n. u0 both chooses and, stretched
/// back onto [0, 1), draws: u0 < P_s gives the lobe with u0 / P_s.
inline Vec3 sample_phong(Vec2 u, const Phong& material, const Vec3& n, const Vec3& wo) {
  const double p_lobe = phong_lobe_probability(material);
  if (u.x < p_lobe)
    return sample_phong_lobe({u.x / p_lobe, u.y}, mirror_direction(wo, n), material.m);
  const Vec2 u_diffuse{(u.x - p_lobe) / (1.0 - p_lobe), u.y};
  return Frame(n).to_world(sample_cosine_hemisphere(u_diffuse));
}

/// p(wi) = P_s p_lobe(wi) + (1 - P_s) max(0, wi . n) / pi per steradian: the pdf of
/// sample_phong.
inline double phong_pdf(const Phong& material, const Vec3& wi, const Vec3& n, const Vec3& wo) {
  const double p_lobe = phong_lobe_probability(material);
  const double lobe = p_lobe > 0.0 ? phong_lobe_pdf(wi, mirror_direction(wo, n), material.m) : 0.0;
  const double diffuse = p_lobe < 1.0 ? cosine_hemisphere_pdf(std::max(0.0, glm::dot(wi, n))) : 0.0;
  return p_lobe * lobe + (1.0 - p_lobe) * diffuse;
}

/// Var[Y] of the lobe's albedo estimator Y = f cos(theta_i) / p_lobe at normal incidence,
/// where E[Y] = rho_s: rho_s^2 / ((m + 1)(m + 3)).
inline double phong_lobe_albedo_variance_at_normal(double rho_s, double m) {
  return rho_s * rho_s / ((m + 1.0) * (m + 3.0));
}

/// An upper bound of Var[Y] at any incidence, given the albedo a = E[Y]:
/// a (Y_max - a) with Y_max = rho_s (m + 2)/(m + 1).
inline double phong_lobe_albedo_variance_bound(double albedo, double rho_s, double m) {
  return albedo * (rho_s * (m + 2.0) / (m + 1.0) - albedo);
}

}  // namespace mcrt
