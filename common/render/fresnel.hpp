#pragma once
/// Light at a smooth boundary between two transparent media of refractive indices eta_i (the
/// side the light comes from) and eta_t (the other side): Snell's law for the refracted
/// direction, and the Fresnel equations for the fraction R of the light that is reflected
/// (unpolarised light; the rest, T = 1 - R, is transmitted: nothing is absorbed at the
/// boundary).
///
///   Snell:    eta_i sin(theta_i) = eta_t sin(theta_t)
///   Fresnel:  r_s = (eta_i cos_i - eta_t cos_t) / (eta_i cos_i + eta_t cos_t)
///             r_p = (eta_t cos_i - eta_i cos_t) / (eta_t cos_i + eta_i cos_t)
///             R = (r_s^2 + r_p^2) / 2
///
/// Where eta_i sin(theta_i) / eta_t > 1 no angle theta_t satisfies Snell's law: total internal
/// reflection, R = 1. R is reciprocal: light going the other way (from the transmitted
/// direction, swapping eta_i and eta_t, cos_i and cos_t) is reflected in the same fraction.

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/math.hpp"

namespace mcrt {

/// cos(theta_t) from cos(theta_i) in [0, 1] and the ratio eta = eta_i / eta_t, by Snell:
/// sin^2(theta_t) = eta^2 (1 - cos^2(theta_i)); nothing where that is >= 1 (total internal
/// reflection; an exactly grazing transmitted ray carries no light either).
inline std::optional<double> refracted_cosine(double cos_i, double eta) {
  const double sin2_t = eta * eta * std::max(0.0, 1.0 - cos_i * cos_i);
  if (sin2_t >= 1.0) return std::nullopt;
  return std::sqrt(1.0 - sin2_t);
}

/// The exact Fresnel reflectance R of a dielectric boundary for unpolarised light, from the
/// cosines of the incident and transmitted angles (both in [0, 1]) and the two indices.
inline double fresnel_dielectric(double cos_i, double cos_t, double eta_i, double eta_t) {
  const double r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
  const double r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
  return 0.5 * (r_s * r_s + r_p * r_p);
}

/// R for light arriving at cos(theta_i) in [0, 1] from the side of index eta_i: 1 under total
/// internal reflection, else the exact Fresnel term with cos(theta_t) from Snell.
inline double fresnel_dielectric(double cos_i, double eta_i, double eta_t) {
  const std::optional<double> cos_t = refracted_cosine(cos_i, eta_i / eta_t);
  if (!cos_t) return 1.0;
  // At cos_i = cos_t = 0 (grazing both ways: eta_i = eta_t) the formula is 0/0; a grazing
  // ray is reflected whole.
  if (cos_i == 0.0) return 1.0;
  return fresnel_dielectric(cos_i, *cos_t, eta_i, eta_t);
}

/// Schlick's approximation to R, as smallpt uses it, only where a comparison with smallpt
/// needs smallpt's own numbers: R0 + (1 - R0)(1 - cos)^5, R0 = ((eta_t - eta_i)/(eta_t + eta_i))^2,
/// with cos the cosine on the side of the smaller index (cos_i entering the denser medium,
/// cos_t leaving it). Exact at normal incidence and at grazing, off by up to a few percent
/// in between.
inline double fresnel_schlick(double cos_less_dense, double eta_i, double eta_t) {
  const double r0 = (eta_t - eta_i) * (eta_t - eta_i) / ((eta_t + eta_i) * (eta_t + eta_i));
  const double c = 1.0 - cos_less_dense;
  return r0 + (1.0 - r0) * c * c * c * c * c;
}

/// The mirror direction of w (unit, pointing away from the surface) about the unit normal n:
/// 2 (w.n) n - w.
inline Vec3 reflect(const Vec3& w, const Vec3& n) { return 2.0 * glm::dot(w, n) * n - w; }

/// The refracted direction of a path: w points away from the surface on the incident side
/// (towards where the path came from), n is the unit normal on that side, cos_i = w.n, eta = eta_i / eta_t and cos_t from refracted_cosine.
/// The result, -eta w + (eta cos_i - cos_t) n, is unit by construction, lies in the plane of w
/// and n on the other side, and satisfies Snell: its tangential part is -eta times w's.
inline Vec3 refract(const Vec3& w, const Vec3& n, double cos_i, double cos_t, double eta) {
  return -eta * w + (eta * cos_i - cos_t) * n;
}

}  // namespace mcrt
