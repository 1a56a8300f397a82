// The glossy lobe of sampling/phong.hpp: its samplers against their pdfs (chi-square, 1e5
// samples each, false-failure rate 1e-4 each), and the estimator it serves, the directional
// albedo f cos / p, against its closed forms and its quadrature (false-failure rate 1e-4).

#include <array>
#include <cmath>
#include <vector>

#include "sampling/phong.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"
#include "sampling/phong_lobe.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

// ---- the lobe round r ----

// On the plain (phi, cos alpha) cells round r, 21 x 11: m = 1 and 10 spread over them (at
// m = 10 the last cos(alpha) cell holds 0.65 of the samples, the first ~1e-11: pooled).
MCRT_STATISTICAL_CHECK(phong_lobe_m1_matches_its_pdf_on_hemisphere_cells, k_sampler_alpha) {
  return phong_lobe_hemisphere_p_value(sample_phong_lobe, phong_lobe_pdf, 1.0, seed,
                                       k_phong_hemisphere_stream,
                                       "phong_lobe_m1_matches_its_pdf_on_hemisphere_cells");
}
MCRT_STATISTICAL_CHECK(phong_lobe_m10_matches_its_pdf_on_hemisphere_cells, k_sampler_alpha) {
  return phong_lobe_hemisphere_p_value(sample_phong_lobe, phong_lobe_pdf, 10.0, seed,
                                       k_phong_hemisphere_stream + 1,
                                       "phong_lobe_m10_matches_its_pdf_on_hemisphere_cells");
}

// On cells of equal pdf measure (phi, cos(alpha)^(m+1)), 21 x 11, ~430 expected in each at
// every m: the sharp lobes (m = 100 .. 1e4) would sit in one plain cos(alpha) cell.
MCRT_STATISTICAL_CHECK(phong_lobe_m1_matches_its_pdf_on_cdf_cells, k_sampler_alpha) {
  return phong_lobe_cdf_p_value<1>(sample_phong_lobe, phong_lobe_pdf, seed, k_phong_cdf_stream,
                                   "phong_lobe_m1_matches_its_pdf_on_cdf_cells");
}
MCRT_STATISTICAL_CHECK(phong_lobe_m10_matches_its_pdf_on_cdf_cells, k_sampler_alpha) {
  return phong_lobe_cdf_p_value<10>(sample_phong_lobe, phong_lobe_pdf, seed, k_phong_cdf_stream + 1,
                                    "phong_lobe_m10_matches_its_pdf_on_cdf_cells");
}
MCRT_STATISTICAL_CHECK(phong_lobe_m100_matches_its_pdf_on_cdf_cells, k_sampler_alpha) {
  return phong_lobe_cdf_p_value<100>(sample_phong_lobe, phong_lobe_pdf, seed,
                                     k_phong_cdf_stream + 2,
                                     "phong_lobe_m100_matches_its_pdf_on_cdf_cells");
}
MCRT_STATISTICAL_CHECK(phong_lobe_m1000_matches_its_pdf_on_cdf_cells, k_sampler_alpha) {
  return phong_lobe_cdf_p_value<1000>(sample_phong_lobe, phong_lobe_pdf, seed,
                                      k_phong_cdf_stream + 3,
                                      "phong_lobe_m1000_matches_its_pdf_on_cdf_cells");
}
MCRT_STATISTICAL_CHECK(phong_lobe_m10000_matches_its_pdf_on_cdf_cells, k_sampler_alpha) {
  return phong_lobe_cdf_p_value<10000>(sample_phong_lobe, phong_lobe_pdf, seed,
                                       k_phong_cdf_stream + 4,
                                       "phong_lobe_m10000_matches_its_pdf_on_cdf_cells");
}

// ---- the full material: diffuse + lobe, on the whole sphere round n ----

// rho_d 0.5, rho_s 0.3, m 10, wo at 30 degrees: a broad lobe mostly above the surface.
MCRT_STATISTICAL_CHECK(phong_material_matches_its_pdf, k_sampler_alpha) {
  return phong_material_p_value(sample_phong, phong_pdf, Phong{0.5, 0.3, 10.0}, 30.0 * k_pi / 180.0,
                                seed, k_phong_material_stream, "phong_material_matches_its_pdf");
}
// rho_d 0.2, rho_s 0.7, m 100, wo at 75 degrees: a sharp lobe with ~1/4 of it below the
// surface, which the sampler returns and the sphere cells count.
MCRT_STATISTICAL_CHECK(phong_material_at_grazing_matches_its_pdf, k_sampler_alpha) {
  return phong_material_p_value(sample_phong, phong_pdf, Phong{0.2, 0.7, 100.0},
                                75.0 * k_pi / 180.0, seed, k_phong_material_stream + 1,
                                "phong_material_at_grazing_matches_its_pdf");
}

// ---- the estimator it serves: the directional albedo ----

// n values of Y = f cos(theta_i) / p with wi drawn by sample_phong from Rng(seed, stream).
std::vector<double> albedo_samples(const Phong& material, double theta_o, std::uint64_t seed,
                                   std::uint64_t stream, std::uint64_t n) {
  const Vec3 normal(0.0, 0.0, 1.0);
  const Vec3 wo(std::sin(theta_o), 0.0, std::cos(theta_o));
  Rng rng(seed, stream);
  std::vector<double> y(n);
  for (double& value : y) {
    const Vec3 wi = sample_phong(rng.uniform2(), material, normal, wo);
    const double pdf = phong_pdf(material, wi, normal, wo);
    const double f_cos = phong_brdf(material, wi, wo, normal) * std::max(0.0, wi.z);
    value = pdf > 0.0 ? f_cos / pdf : 0.0;  // below the surface: f = 0, the sample is lost
  }
  return y;
}

double mean_of(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}
double variance_of(const std::vector<double>& v) {
  const double mean = mean_of(v);
  double sum = 0.0;
  for (double x : v) sum += (x - mean) * (x - mean);
  return sum / static_cast<double>(v.size() - 1);
}

// A white-ish lobe (rho_s 0.8) seen at normal incidence, m = 1, 10, 1000: E[Y] = rho_s with
// the closed-form Var[Y] = rho_s^2 / ((m + 1)(m + 3)) (z-test of the mean on 1e5 samples) and
// the sample variance against that closed form (variance_z_test on another 1e5); then at
// oblique incidence (m = 10 at 60 degrees, m = 1000 at 80) the mean against the quadrature
// albedo (phong_lobe_albedo, accurate to ~1e-10, far below the standard error ~1e-3) by a
// t-test. Eight independent tests on their own streams, Sidak-combined: rate 1e-4.
MCRT_STATISTICAL_CHECK(phong_albedo_estimator_matches_its_closed_forms, 1e-4) {
  constexpr std::uint64_t k_n = 100000;
  const double rho_s = 0.8;
  std::vector<double> p;
  std::uint64_t stream = k_phong_albedo_stream;
  for (double m : {1.0, 10.0, 1000.0}) {
    const Phong lobe{0.0, rho_s, m};
    const double variance = phong_lobe_albedo_variance_at_normal(rho_s, m);
    const std::vector<double> for_mean = albedo_samples(lobe, 0.0, seed, stream++, k_n);
    p.push_back(z_test_p_value(mean_of(for_mean), rho_s, std::sqrt(variance / k_n)));
    const std::vector<double> for_variance = albedo_samples(lobe, 0.0, seed, stream++, k_n);
    p.push_back(variance_z_test_p_value(for_variance, variance));
  }
  for (const auto& [m, degrees] : {std::pair{10.0, 60.0}, std::pair{1000.0, 80.0}}) {
    const Phong lobe{0.0, rho_s, m};
    const double theta_o = degrees * k_pi / 180.0;
    const std::vector<double> y = albedo_samples(lobe, theta_o, seed, stream++, k_n);
    p.push_back(t_test_p_value(mean_of(y), variance_of(y), k_n, phong_lobe_albedo(lobe, theta_o)));
  }
  return sidak_p_value(p);
}

}  // namespace
