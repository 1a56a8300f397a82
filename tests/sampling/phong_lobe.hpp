#pragma once
// What the Phong tests share (tests/sampling/phong_test.cpp, tests/sampling/phong_checks.cpp and the
// known-bug tests): a basis round the lobe's axis built independently of Frame, the binning of
// the lobe on cells of equal pdf measure, the chi-square p-values of the lobe and of the full
// material, and the directional albedo by quadrature.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/math.hpp"
#include "sampling/phong.hpp"
#include "stats/binning.hpp"
#include "stats/chi_square.hpp"
#include "stats/sampler_tests.hpp"

namespace mcrt::testing {

/// An orthonormal basis with `axis` as z, its x in the plane of axis and `toward` (when they
/// differ; any x otherwise), by Gram-Schmidt: not Frame, so a wrong Frame cannot hide itself.
struct AxisBasis {
  Vec3 x, y, z;

  AxisBasis(const Vec3& axis, const Vec3& toward) : z(axis) {
    Vec3 along = toward - glm::dot(toward, axis) * axis;
    if (glm::length(along) < 1e-6) {  // toward is (nearly) the axis: any x will do
      const Vec3 helper = std::abs(axis.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
      along = helper - glm::dot(helper, axis) * axis;
    }
    x = glm::normalize(along);
    y = glm::cross(z, x);
  }
  Vec3 to_local(const Vec3& w) const { return {glm::dot(w, x), glm::dot(w, y), glm::dot(w, z)}; }
  Vec3 to_world(const Vec3& local) const { return local.x * x + local.y * y + local.z * z; }
};

namespace detail {

// The lobe's hemisphere on (phi, t) with t = cos(alpha)^(M + 1), the CDF of cos(alpha): every
// cell of equal (phi, t) area holds the same probability under the pdf (m + 1)/(2 pi) cos^m,
// however sharp the lobe. cos(alpha) = t^(1/(M+1)); 1 - cos by expm1 (the cells near the axis
// are 1e-5 wide at M = 1e4).
template <int M>
Vec3 lobe_cdf_point(double phi, double t) {
  const double log_c = std::log(t) / (M + 1.0);
  const double c = std::exp(log_c);
  const double s = std::sqrt(-std::expm1(log_c) * (1.0 + c));
  return {s * std::cos(phi), s * std::sin(phi), c};
}
template <int M>
std::optional<Vec2> lobe_cdf_parameters(const Vec3& w) {
  const std::optional<Vec2> phi_c = hemisphere_parameters(w);
  if (!phi_c) return std::nullopt;
  return Vec2(phi_c->x, std::pow(std::clamp(phi_c->y, 0.0, 1.0), M + 1.0));
}

}  // namespace detail

/// 21 phi cells by 11 cells of t = cos(alpha)^(M + 1) (odd counts, as hemisphere_binning).
/// The density of (phi, t) is p(w) dw / (dphi dt) = p(w) / ((M + 1) cos^M(alpha)).
template <int M>
Binning<Vec3> lobe_cdf_binning() {
  return {{"lobe (phi, cos(alpha)^(m+1))", "phi (rad)", "cos(alpha)^(m+1)", 0.0, k_two_pi, 0.0, 1.0,
           21, 11, 1.0},
          &detail::lobe_cdf_point<M>,
          &detail::lobe_cdf_parameters<M>};
}

/// The generator streams of the Phong checks (tests/sampling/phong_checks.cpp), apart from the
/// other checks' streams; the known-bug tests reuse them, so they see the same uniforms.
inline constexpr std::uint64_t k_phong_hemisphere_stream = 320;  // + 0, 1: m = 1, 10
inline constexpr std::uint64_t k_phong_cdf_stream = 330;         // + 0..4: m = 1 .. 1e4
inline constexpr std::uint64_t k_phong_material_stream = 340;    // + 0, 1
inline constexpr std::uint64_t k_phong_albedo_stream = 350;      // + 0..7

/// The mirror direction the lobe tests use: wo at 40 degrees from a tilted normal, so r is
/// tilted against the world axes and against n, and part of the lobe is below the surface.
inline Vec3 phong_test_normal() { return glm::normalize(Vec3(0.2, -0.3, 0.9)); }
inline Vec3 phong_test_reflected() {
  const Vec3 n = phong_test_normal();
  const AxisBasis basis(n, Vec3(1, 0, 0));
  const double theta_o = 40.0 * k_pi / 180.0;
  const Vec3 wo = basis.to_world({std::sin(theta_o), 0.0, std::cos(theta_o)});
  return mirror_direction(wo, n);
}

/// Chi-square p-value (1e5 samples, alpha 1e-4, as every sampler test) of a lobe sampler
/// Vec3(Vec2 u, Vec3 r, double m) against a lobe pdf double(Vec3 wi, Vec3 r, double m), on
/// the cells of lobe_cdf_binning<M> in a basis round r.
template <int M, class Sampler, class Pdf>
double phong_lobe_cdf_p_value(const Sampler& sample, const Pdf& pdf, std::uint64_t seed,
                              std::uint64_t stream, const std::string& name) {
  const Vec3 r = phong_test_reflected();
  const AxisBasis basis(r, phong_test_normal());
  const auto local_sample = [&](Vec2 u) { return basis.to_local(sample(u, r, double(M))); };
  const auto density = [&](const Vec3& local) {  // per unit (phi, t): see lobe_cdf_binning
    return pdf(basis.to_world(local), r, double(M)) / ((M + 1.0) * std::pow(local.z, double(M)));
  };
  return chi_square_sampler_p_value(local_sample, density, lobe_cdf_binning<M>(), seed,
                                    {name, k_sampler_samples, stream, k_sampler_alpha});
}

/// The same on the plain hemisphere cells (phi, cos(alpha)) round r (sampler_tests.hpp): fine
/// for small m, where the lobe spreads over many cos(alpha) cells.
template <class Sampler, class Pdf>
double phong_lobe_hemisphere_p_value(const Sampler& sample, const Pdf& pdf, double m,
                                     std::uint64_t seed, std::uint64_t stream,
                                     const std::string& name) {
  const Vec3 r = phong_test_reflected();
  const AxisBasis basis(r, phong_test_normal());
  const auto local_sample = [&](Vec2 u) { return basis.to_local(sample(u, r, m)); };
  const auto local_pdf = [&](const Vec3& local) { return pdf(basis.to_world(local), r, m); };
  return hemisphere_sampler_p_value(local_sample, local_pdf, seed, stream, name);
}

/// Chi-square p-value of a full-material sampler Vec3(Vec2 u, Phong, n, wo) against its pdf
/// double(Phong, wi, n, wo) on the whole sphere (21 x 21 cells, in a basis round n): the lobe's
/// samples below the surface are counted too. wo at theta_o from n.
template <class Sampler, class Pdf>
double phong_material_p_value(const Sampler& sample, const Pdf& pdf, const Phong& material,
                              double theta_o, std::uint64_t seed, std::uint64_t stream,
                              const std::string& name) {
  const Vec3 n = phong_test_normal();
  const AxisBasis basis(n, Vec3(1, 0, 0));
  const Vec3 wo = basis.to_world({std::sin(theta_o), 0.0, std::cos(theta_o)});
  const auto local_sample = [&](Vec2 u) { return basis.to_local(sample(u, material, n, wo)); };
  const auto local_pdf = [&](const Vec3& local) {
    return pdf(material, basis.to_world(local), n, wo);
  };
  return sphere_sampler_p_value(local_sample, local_pdf, seed, stream, name);
}

/// The range of v = -log(t) = -(m + 1) log(cos alpha) the quadratures below cover: t is the
/// lobe's CDF, so the rest, v > 50, holds a fraction e^-50 < 2e-22 of the lobe.
inline constexpr double k_lobe_v_max = 50.0;

/// The directional albedo a(wo) = int f(wi, wo) cos(theta_i) dwi of a lobe (rho_d = 0), wo at
/// theta_o from the normal, by nested adaptive Gauss-Kronrod quadrature of phong_brdf itself.
/// wi is parameterised round r by (phi, v) with cos(alpha) = c = exp(-v / (m + 1)), v >= 0,
/// so dw = dphi dc = dphi dv c / (m + 1) and the integrand, f cos(theta_i) c / (m + 1) ~ e^-v,
/// is smooth and equally wide at any m. It has kinks only where the lobe meets the horizon (in
/// phi at cos(phi_0) = -c cos(theta_r) / (s sin(theta_r)); in v where alpha = 90 degrees -
/// theta_r): the ranges are split there, and each smooth piece is integrated by 31-point
/// Gauss-Kronrod to relative tolerance 1e-11 (phi in [0, pi] by symmetry, doubled).
inline double phong_lobe_albedo(const Phong& lobe, double theta_o) {
  using Quadrature = boost::math::quadrature::gauss_kronrod<double, 31>;
  constexpr unsigned k_depth = 8;
  constexpr double k_tolerance = 1e-11;
  const Vec3 n(0.0, 0.0, 1.0);
  const double sin_o = std::sin(theta_o), cos_o = std::cos(theta_o);
  const Vec3 wo(sin_o, 0.0, cos_o);
  const Vec3 r = mirror_direction(wo, n);
  const AxisBasis basis(r, n);  // n = cos(theta_o) z + sin(theta_o) x
  const double m = lobe.m;
  const auto over_phi = [&](double v) {
    const double log_c = -v / (m + 1.0);
    const double c = std::exp(log_c);
    const double s = std::sqrt(-std::expm1(log_c) * (1.0 + c));
    const double jacobian = c / (m + 1.0);  // dw / (dphi dv)
    const auto integrand = [&](double phi) {
      const Vec3 wi = basis.to_world({s * std::cos(phi), s * std::sin(phi), c});
      return phong_brdf(lobe, wi, wo, n) * std::max(0.0, glm::dot(wi, n)) * jacobian;
    };
    // n . wi = c cos(theta_o) + s sin(theta_o) cos(phi) crosses 0 at phi_0, if at all.
    const double denominator = s * sin_o;
    const double cos_phi0 = denominator > 0.0 ? -c * cos_o / denominator : -2.0;
    if (cos_phi0 <= -1.0 || cos_phi0 >= 1.0)
      return 2.0 * Quadrature::integrate(integrand, 0.0, k_pi, k_depth, k_tolerance);
    const double phi0 = std::acos(cos_phi0);
    return 2.0 * (Quadrature::integrate(integrand, 0.0, phi0, k_depth, k_tolerance) +
                  Quadrature::integrate(integrand, phi0, k_pi, k_depth, k_tolerance));
  };
  // The lobe first meets the horizon at cos(alpha) = sin(theta_o): v = -(m + 1) log sin(theta_o).
  const double v_star = sin_o > 0.0 ? -(m + 1.0) * std::log(sin_o) : k_lobe_v_max;
  if (v_star <= 0.0 || v_star >= k_lobe_v_max)
    return Quadrature::integrate(over_phi, 0.0, k_lobe_v_max, k_depth, k_tolerance);
  return Quadrature::integrate(over_phi, 0.0, v_star, k_depth, k_tolerance) +
         Quadrature::integrate(over_phi, v_star, k_lobe_v_max, k_depth, k_tolerance);
}

}  // namespace mcrt::testing
