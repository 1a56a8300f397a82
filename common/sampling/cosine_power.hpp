#pragma once
/// Importance sampling on the hemisphere z >= 0 (the local frame, normal = +z): samplers whose
/// pdfs follow, or deliberately do not follow, the cosine of the rendering equation. Each
/// sampler is a pure function of u in [0,1)^2 beside its pdf per steradian.
///
///   the cosine-power family  p_m(w) = (m + 1) / (2 pi) cos^m(theta)
///     m = 0 is uniform, m = 1 cosine-weighted, larger m crowd the directions round the normal;
///   a bad pdf that favours grazing directions  p_g(w) = 2 sin(theta) / pi^2
///     zero along the normal, largest at the horizon: the opposite of the integrand's cosine.
///
/// HemispherePdf names one of them (with the uniform and Malley cosine samplers of
/// sampling/hemisphere.hpp), so a renderer can be handed the pdf to draw from.

#include <algorithm>
#include <cmath>
#include <string>

#include "core/cos_sin.hpp"
#include "core/math.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt {

/// p_m: solid angle is dw = d(cos theta) d(phi), so cos theta has density (m + 1) z^m on [0, 1]
/// and CDF z^(m + 1) = u0: cos theta = u0^(1 / (m + 1)), phi = 2 pi u1.
inline Vec3 sample_cosine_power_hemisphere(Vec2 u, int m) {
  // ASSIGNMENT a2.2 BEGIN needs=a2.1 withheld stub: (void)u; (void)m; NOT_IMPLEMENTED(sample_cosine_power_hemisphere);
  const double cos_theta = std::pow(u.x, 1.0 / (m + 1.0));
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  return {sin_theta * circle.x, sin_theta * circle.y, cos_theta};
  // ASSIGNMENT a2.2 END
}
/// (m + 1) / (2 pi) cos^m(theta): the integral of cos^m over the hemisphere is 2 pi / (m + 1).
inline double cosine_power_hemisphere_pdf(double cos_theta, int m) {
  // ASSIGNMENT a2.2 BEGIN needs=a2.1 withheld stub: (void)cos_theta; (void)m; NOT_IMPLEMENTED(cosine_power_hemisphere_pdf);
  return (m + 1.0) * k_inv_two_pi * std::pow(std::max(0.0, cos_theta), m);
  // ASSIGNMENT a2.2 END
}

/// p_g = 2 sin(theta) / pi^2. theta has density p_g sin(theta) 2 pi = (4 / pi) sin^2(theta) on
/// [0, pi/2], CDF (2 theta - sin 2 theta) / pi. So t = 2 theta solves t - sin t = pi u0
/// (Kepler's equation at eccentricity 1), by Newton's method: g(t) = t - sin t - pi u0 is
/// convex and increasing, so from a start with g >= 0 the steps fall monotonically onto the
/// root. Start: sin t <= t - t^3/6 + t^5/120 gives g(1.3 (6 pi u0)^(1/3)) >= 0 for t <= pi.
inline Vec3 sample_grazing_hemisphere(Vec2 u) {
  const double target = k_pi * u.x;
  double t = std::min(k_pi, 1.3 * std::cbrt(6.0 * target));
  for (int i = 0; i < 60 && t > 0.0; ++i) {
    const double half_sin = std::sin(0.5 * t);
    const double slope = 2.0 * half_sin * half_sin;  // 1 - cos t, without cancellation
    const double step = (t - std::sin(t) - target) / slope;
    if (!(step > 1e-15 * t)) break;  // converged (or at the root to round-off)
    t -= step;
  }
  const double theta = 0.5 * t;
  const double phi = k_two_pi * u.y;
  const double sin_theta = std::sin(theta);
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), std::cos(theta)};
}
/// 2 sin(theta) / pi^2: the integral of sin(theta) over the hemisphere is pi^2 / 2.
inline double grazing_hemisphere_pdf(double cos_theta) {
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return 2.0 * sin_theta * k_inv_pi * k_inv_pi;
}

/// One of the pdfs chapter 07 draws directions from.
struct HemispherePdf {
  enum Kind { uniform, cosine, cosine_power, grazing };
  Kind kind = uniform;
  int m = 0;  ///< the power of cos(theta), for cosine_power
};

/// The member of the family p ~ cos^m: m = 0 is the uniform sampler, m = 1 Malley's cosine
/// sampler (sampling/hemisphere.hpp), other m the cosine-power sampler.
inline HemispherePdf cosine_power_pdf(int m) {
  if (m == 0) return {HemispherePdf::uniform, 0};
  if (m == 1) return {HemispherePdf::cosine, 1};
  return {HemispherePdf::cosine_power, m};
}

/// "uniform", "cosine", "cos^m" or "grazing".
inline std::string pdf_name(const HemispherePdf& pdf) {
  switch (pdf.kind) {
    case HemispherePdf::uniform: return "uniform";
    case HemispherePdf::cosine: return "cosine";
    case HemispherePdf::cosine_power: return "cos^" + std::to_string(pdf.m);
    case HemispherePdf::grazing: return "grazing";
  }
  return "?";
}

/// A local direction drawn from `pdf`.
inline Vec3 sample_hemisphere(const HemispherePdf& pdf, Vec2 u) {
  switch (pdf.kind) {
    case HemispherePdf::uniform: return sample_uniform_hemisphere(u);
    case HemispherePdf::cosine: return sample_cosine_hemisphere(u);
    case HemispherePdf::cosine_power: return sample_cosine_power_hemisphere(u, pdf.m);
    case HemispherePdf::grazing: return sample_grazing_hemisphere(u);
  }
  return {0.0, 0.0, 1.0};
}

/// Its density per steradian at a direction with cos(theta) = cos_theta.
inline double hemisphere_pdf(const HemispherePdf& pdf, double cos_theta) {
  switch (pdf.kind) {
    case HemispherePdf::uniform: return uniform_hemisphere_pdf();
    case HemispherePdf::cosine: return cosine_hemisphere_pdf(cos_theta);
    case HemispherePdf::cosine_power: return cosine_power_hemisphere_pdf(cos_theta, pdf.m);
    case HemispherePdf::grazing: return grazing_hemisphere_pdf(cos_theta);
  }
  return 0.0;
}

}  // namespace mcrt
