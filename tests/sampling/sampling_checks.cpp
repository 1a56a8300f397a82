// Every sampler of common/sampling/ against its own pdf: a chi-square goodness-of-fit test
// of 1e5 samples on equal-measure cells (false-failure rate 1e-4 each), and the pdf's integral
// over its domain, which must be 1.

#include <array>

#include <gtest/gtest.h>

#include "sampling/sampling.hpp"
#include "stats/check.hpp"
#include "stats/chi_square.hpp"
#include "stats/hypothesis.hpp"
#include "stats/sampler_tests.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

double square_pdf(const Vec2&) { return uniform_square_pdf(); }
double disk_pdf(const Vec2&) { return uniform_disk_pdf(); }
double uniform_hemisphere_pdf_at(const Vec3&) { return uniform_hemisphere_pdf(); }
double cosine_hemisphere_pdf_at(const Vec3& w) { return cosine_hemisphere_pdf(w.z); }
double uniform_sphere_pdf_at(const Vec3&) { return uniform_sphere_pdf(); }

MCRT_STATISTICAL_CHECK(uniform_square_sampler_matches_its_pdf, k_sampler_alpha) {
  return square_sampler_p_value(sample_uniform_square, square_pdf, seed, k_square_stream,
                                "uniform_square_sampler_matches_its_pdf");
}

MCRT_STATISTICAL_CHECK(uniform_disk_sampler_matches_its_pdf, k_sampler_alpha) {
  return disk_sampler_p_value(sample_uniform_disk, disk_pdf, seed, k_disk_stream,
                              "uniform_disk_sampler_matches_its_pdf");
}

MCRT_STATISTICAL_CHECK(uniform_hemisphere_sampler_matches_its_pdf, k_sampler_alpha) {
  return hemisphere_sampler_p_value(sample_uniform_hemisphere, uniform_hemisphere_pdf_at, seed,
                                    k_uniform_hemisphere_stream,
                                    "uniform_hemisphere_sampler_matches_its_pdf");
}

MCRT_STATISTICAL_CHECK(uniform_sphere_sampler_matches_its_pdf, k_sampler_alpha) {
  return sphere_sampler_p_value(sample_uniform_sphere, uniform_sphere_pdf_at, seed,
                                k_uniform_sphere_stream, "uniform_sphere_sampler_matches_its_pdf");
}

MCRT_STATISTICAL_CHECK(cosine_hemisphere_sampler_matches_its_pdf, k_sampler_alpha) {
  return hemisphere_sampler_p_value(sample_cosine_hemisphere, cosine_hemisphere_pdf_at, seed,
                                    k_cosine_hemisphere_stream,
                                    "cosine_hemisphere_sampler_matches_its_pdf");
}

// The direction w seen from an orthonormal basis around n built here by Gram-Schmidt,
// independently of Frame. Both samplers are symmetric about the normal, so any such basis
// sees the same distribution of (phi, cos theta) as the sampler's own local frame.
Vec3 in_reference_basis(const Vec3& n, const Vec3& w) {
  const Vec3 helper = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 t = glm::normalize(helper - glm::dot(helper, n) * n);
  const Vec3 b = glm::cross(n, t);
  return {glm::dot(w, t), glm::dot(w, b), glm::dot(w, n)};
}

// Both hemisphere samplers turned into world space by Frame(n), for normals along and against
// the axes and in general position (Frame's formula branches on the sign of n.z): the world
// directions must still follow the pdf around n. Ten chi-square tests of 2e4 samples on
// 11 x 7 cells (~260 per cell), run together on streams 100-109 (apart from the other
// sampler checks'): Sidak-combined, false-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(hemisphere_samplers_keep_their_pdf_in_world_frames, k_sampler_alpha) {
  const std::array<Vec3, 5> normals{Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0),
                                    glm::normalize(Vec3(1, 2, 3)),
                                    glm::normalize(Vec3(-0.3, 0.1, -0.9))};
  const Binning<Vec3> binning = hemisphere_binning(11, 7);
  constexpr std::uint64_t k_samples = 20000;
  std::array<ChiSquareResult, 2 * normals.size()> results;
  std::uint64_t stream = 100;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const Vec3 n = normals[i];
    const Frame frame(n);
    const auto uniform = [&](Vec2 u) {
      return in_reference_basis(n, frame.to_world(sample_uniform_hemisphere(u)));
    };
    const auto cosine = [&](Vec2 u) {
      return in_reference_basis(n, frame.to_world(sample_cosine_hemisphere(u)));
    };
    results[2 * i] = chi_square_sampler_test(uniform, uniform_hemisphere_pdf_at, binning, seed,
                                             k_samples, stream++);
    results[2 * i + 1] = chi_square_sampler_test(cosine, cosine_hemisphere_pdf_at, binning, seed,
                                                 k_samples, stream++);
  }
  std::array<double, results.size()> p{};
  std::size_t worst = 0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    p[k] = results[k].p_value;
    if (p[k] < p[worst]) worst = k;
  }
  const double family_p = sidak_p_value(p);
  if (family_p < k_sampler_alpha)
    report_chi_square_failure({"hemisphere_samplers_keep_their_pdf_in_world_frames"},
                              results[worst], binning);
  return family_p;
}

// The pdfs integrate to 1 over their domains. The quadrature is exact up to round-off here
// (each pdf is constant or linear in cos(theta) on a cell, and 15-point Gauss-Kronrod is
// exact for polynomials of degree 22); 1e-9 leaves ample room for round-off over 231 cells
// and fails any pdf off by a constant factor.
constexpr double k_pdf_integral_tolerance = 1e-9;

TEST(SamplerPdfTest, UniformSquarePdfIntegratesToOne) {
  EXPECT_NEAR(pdf_integral(square_pdf, sampler_square_binning()), 1.0, k_pdf_integral_tolerance);
}

TEST(SamplerPdfTest, UniformDiskPdfIntegratesToOne) {
  EXPECT_NEAR(pdf_integral(disk_pdf, sampler_disk_binning()), 1.0, k_pdf_integral_tolerance);
}

TEST(SamplerPdfTest, UniformSpherePdfIntegratesToOne) {
  EXPECT_NEAR(pdf_integral(uniform_sphere_pdf_at, sphere_binning(21, 21)), 1.0,
              k_pdf_integral_tolerance);
}

TEST(SamplerPdfTest, UniformHemispherePdfIntegratesToOne) {
  EXPECT_NEAR(pdf_integral(uniform_hemisphere_pdf_at, sampler_hemisphere_binning()), 1.0,
              k_pdf_integral_tolerance);
}

TEST(SamplerPdfTest, CosineHemispherePdfIntegratesToOne) {
  EXPECT_NEAR(pdf_integral(cosine_hemisphere_pdf_at, sampler_hemisphere_binning()), 1.0,
              k_pdf_integral_tolerance);
}

}  // namespace
