// Known bugs are caught. Each test below takes a deliberately wrong variant of a piece of the
// core from the tests/<layer>/*_known_bugs.hpp files (where every variant is written once) and asserts that the
// statistical test the real piece passes in the suite rejects it: the same test function, the
// same sample sizes, the same seed (k_suite_seed, or the suite's seed offset for that check)
// and the same alpha. The real piece is run beside it, so a test that rejects everything
// would fail here too. (The wrong path tracers are in tests/render/path_tracer_test.cpp, the wrong
// Monte Carlo estimators in tests/integration/monte_carlo_test.cpp, the wrong furnace moments in
// tests/render/recursive_estimator_test.cpp.)

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "integration/integrands.hpp"
#include "integration/log_grid.hpp"
#include "integration/quadrature.hpp"
#include "integration/monte_carlo_known_bugs.hpp"
#include "sampling/sampling_known_bugs.hpp"
#include "render/two_render_error.hpp"
#include "sampling/sampling.hpp"
#include "stats/check.hpp"
#include "stats/convergence.hpp"
#include "io/plot.hpp"
#include "stats/report.hpp"
#include "stats/sampler_tests.hpp"
#include "io/image_file_decoding.hpp"
#include "sampling/phong_lobe.hpp"
#include "support/small_trials.hpp"
#include "render/two_render_error_check.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

constexpr std::uint64_t k_seed = k_suite_seed;

class KnownBugsTest : public ::testing::Test {
 protected:
  // The wrong variants fail on purpose; their failure reports would only be noise. (The
  // report of one of them is written on purpose by FailureReportPointsAtTheWrongRadius.)
  void SetUp() override { set_failure_reports(false); }
  void TearDown() override { set_failure_reports(true); }
};

// ---- Samplers: chi-square against the sampler's own pdf (sampler_tests.hpp, alpha 1e-4) ----

double disk_pdf(const Vec2&) { return uniform_disk_pdf(); }
double uniform_hemisphere_pdf_at(const Vec3&) { return uniform_hemisphere_pdf(); }
double cosine_hemisphere_pdf_at(const Vec3& w) { return cosine_hemisphere_pdf(w.z); }

TEST_F(KnownBugsTest, DiskSamplerWithRadiusUIsRejected) {
  EXPECT_GE(disk_sampler_p_value(sample_uniform_disk, disk_pdf, k_seed, k_disk_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(disk_sampler_p_value(disk_with_radius_u, disk_pdf, k_seed, k_disk_stream, "wrong"),
            k_sampler_alpha);
}

TEST_F(KnownBugsTest, HemisphereSamplerWhosePdfClaimsOneOverPiIsRejected) {
  EXPECT_GE(hemisphere_sampler_p_value(sample_uniform_hemisphere, uniform_hemisphere_pdf_at, k_seed,
                                       k_uniform_hemisphere_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(hemisphere_sampler_p_value(sample_uniform_hemisphere, hemisphere_pdf_one_over_pi,
                                       k_seed, k_uniform_hemisphere_stream, "wrong"),
            k_sampler_alpha);
}

TEST_F(KnownBugsTest, CosineSamplerWithAnExtraFactorTwoIsRejected) {
  EXPECT_GE(hemisphere_sampler_p_value(sample_cosine_hemisphere, cosine_hemisphere_pdf_at, k_seed,
                                       k_cosine_hemisphere_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(hemisphere_sampler_p_value(sample_cosine_hemisphere, cosine_pdf_times_two, k_seed,
                                       k_cosine_hemisphere_stream, "wrong"),
            k_sampler_alpha);
}

// The Phong lobe's checks (tests/sampling/phong_checks.cpp): the same cells, streams and seed.
TEST_F(KnownBugsTest, PhongLobePdfNormalisedWithMPlusTwoIsRejected) {
  EXPECT_GE(phong_lobe_cdf_p_value<10>(sample_phong_lobe, phong_lobe_pdf, k_seed,
                                       k_phong_cdf_stream + 1, "right"),
            k_sampler_alpha);
  EXPECT_LT(phong_lobe_cdf_p_value<10>(sample_phong_lobe, phong_lobe_pdf_with_m_plus_2, k_seed,
                                       k_phong_cdf_stream + 1, "wrong"),
            k_sampler_alpha);
  EXPECT_LT(phong_lobe_hemisphere_p_value(sample_phong_lobe, phong_lobe_pdf_with_m_plus_2, 10.0,
                                          k_seed, k_phong_hemisphere_stream + 1, "wrong"),
            k_sampler_alpha);
}

TEST_F(KnownBugsTest, PhongLobeSampledWithCosUToOneOverMIsRejected) {
  EXPECT_LT(phong_lobe_cdf_p_value<10>(sample_phong_lobe_cos_u_to_one_over_m, phong_lobe_pdf,
                                       k_seed, k_phong_cdf_stream + 1, "wrong"),
            k_sampler_alpha);
  EXPECT_LT(phong_lobe_hemisphere_p_value(sample_phong_lobe_cos_u_to_one_over_m, phong_lobe_pdf,
                                          1.0, k_seed, k_phong_hemisphere_stream, "wrong"),
            k_sampler_alpha);
}

TEST_F(KnownBugsTest, PhongMaterialPdfMixedHalfAndHalfIsRejected) {
  const Phong material{0.5, 0.3, 10.0};
  const double theta_o = 30.0 * k_pi / 180.0;
  EXPECT_GE(phong_material_p_value(sample_phong, phong_pdf, material, theta_o, k_seed,
                                   k_phong_material_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(phong_material_p_value(sample_phong, phong_pdf_mixed_half_and_half, material, theta_o,
                                   k_seed, k_phong_material_stream, "wrong"),
            k_sampler_alpha);
}

// Reddish (too many) and bluish (too few) pixels of a heat map's plot area, in each half along x
// (`across`) or along y (first half the bottom). The colour bar, right of the plot area, is
// left out: the plot spans the left 80% of the image or less.
struct HeatMapSides {
  int red_first_half = 0, red_second_half = 0, blue_first_half = 0, blue_second_half = 0;
};
HeatMapSides heat_map_sides(const std::filesystem::path& png_path, bool across) {
  std::ifstream in(png_path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  HeatMapSides sides;
  if (bytes.empty()) {
    ADD_FAILURE() << "no heat map at " << png_path;
    return sides;
  }
  const DecodedPng png = decode_png(bytes);
  const int plot_width = png.width * 4 / 5;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < plot_width; ++x) {
      const int r = png.at(x, y, 0), b = png.at(x, y, 2);
      // the palette runs blue - white - red; grey text and white background are neither
      const bool red = r - b > 40, blue = b - r > 15;
      const bool first = across ? x < plot_width / 2 : y >= png.height / 2;
      (first ? sides.red_first_half : sides.red_second_half) += red;
      (first ? sides.blue_first_half : sides.blue_second_half) += blue;
    }
  return sides;
}

// The failure report of the r = u disk shows where it is wrong: far too many samples in the
// innermost ring (r^2 < 1/11 holds 30% of them, not 9%) and too few in the outermost.
TEST_F(KnownBugsTest, FailureReportPointsAtTheWrongRadius) {
  const Binning<Vec2> binning = sampler_disk_binning();
  const ChiSquareResult r = chi_square_sampler_test(disk_with_radius_u, disk_pdf, binning, k_seed,
                                                    k_sampler_samples, k_disk_stream);
  double inner_observed = 0.0, inner_expected = 0.0, outer_observed = 0.0, outer_expected = 0.0;
  for (const CellCount& c : r.cells) {
    if (c.u_index == 0) inner_observed += c.observed, inner_expected += c.expected;
    if (c.u_index == binning.u_cells - 1)
      outer_observed += c.observed, outer_expected += c.expected;
  }
  // sqrt(1/11) = 0.3015 of the samples; 1e5 samples put the fraction within 0.005 (3.5 sigma).
  EXPECT_NEAR(inner_observed / k_sampler_samples, std::sqrt(1.0 / 11.0), 0.005);
  EXPECT_NEAR(inner_expected / k_sampler_samples, 1.0 / 11.0, 1e-9);
  EXPECT_LT(outer_observed, 0.6 * outer_expected);  // 1 - sqrt(10/11) = 0.047 vs 0.091
  const auto csv = write_chi_square_report(failure_report_root() / "known_bug_disk_r_equals_u",
                                           "known_bug_disk_r_equals_u", r, binning);
  EXPECT_TRUE(std::filesystem::exists(csv));
  // What a student sees: the heat map (r^2 across, phi up) is red (too many) at the left, the
  // inner rings, and blue (too few) at the right, the outer ones.
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed: no heat map to look at";
  const HeatMapSides sides =
      heat_map_sides(csv.parent_path() / "known_bug_disk_r_equals_u.png", true);
  EXPECT_GT(sides.red_first_half, 10 * sides.red_second_half);
  EXPECT_GT(sides.blue_second_half, 10 * sides.blue_first_half);
}

// The same for the cosine hemisphere whose disk point sits at r = u0 (phi across, cos(theta)
// up): too many samples near the pole (red at the top), too few at the horizon (blue at the
// bottom). With the header skipped twice gnuplot drew no map at all for this grid.
TEST_F(KnownBugsTest, FailureReportOfTheHemispherePointsAtThePole) {
  const Binning<Vec3> binning = sampler_hemisphere_binning();
  const ChiSquareResult r =
      chi_square_sampler_test(cosine_hemisphere_with_radius_u, cosine_hemisphere_pdf_at, binning,
                              k_seed, k_sampler_samples, k_cosine_hemisphere_stream);
  EXPECT_LT(r.p_value, k_sampler_alpha);
  const auto csv = write_chi_square_report(failure_report_root() / "known_bug_cosine_r_equals_u",
                                           "known_bug_cosine_r_equals_u", r, binning);
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed: no heat map to look at";
  const HeatMapSides sides =
      heat_map_sides(csv.parent_path() / "known_bug_cosine_r_equals_u.png", false);
  EXPECT_GT(sides.red_second_half, 10 * sides.red_first_half);  // red at the top: the pole
  EXPECT_GT(sides.blue_first_half, 10 * sides.red_first_half);  // the lower half blue, not red
}

// ---- Trials of a small estimate (tests/support/small_trials.hpp, alpha 1e-4) ----------------

TEST_F(KnownBugsTest, EstimatorDividingByNMinusOneIsRejected) {
  EXPECT_GE(small_trials_p_value(gaussian_estimate, k_seed), 1e-4);
  EXPECT_LT(small_trials_p_value(estimate_dividing_by_n_minus_one, k_seed), 1e-4);
}

TEST_F(KnownBugsTest, GeneratorStreamReusedAcrossTrialsIsRejected) {
  EXPECT_LT(small_trials_p_value(gaussian_estimate, k_seed, SameStreamTrials{}), 1e-4);
}

// ---- The two-render error against Var[L] / spp (tests/render/two_render_error_check.hpp, 1e-4) ----

TEST_F(KnownBugsTest, TwoRenderErrorWithoutTheHalfIsRejected) {
  EXPECT_GE(two_render_error_p_value(k_seed, two_render_mean_squared_error), 1e-4);
  EXPECT_LT(two_render_error_p_value(k_seed, two_render_error_without_the_half), 1e-4);
}

// ---- The trapezoid rule: its n^-2 rate ------------------------------------------------------

// The fitted slope of log|T_n - I| against log n over n = 10..1000, e^(-x^2) on [0, 1]. The
// error is deterministic, so the test is a tolerance, not a p-value: the error is
// c h^2 = c / (n - 1)^2, whose local slope -2 n / (n - 1) runs from -2.22 to -2.002, and the
// fit over the grid gives about -2.04; +-0.1 covers that and is ten times smaller than the
// distance to the slope -1 of an O(h) error.
template <class Rule>
SlopeEstimate trapezoid_slope(const Rule& rule) {
  const Gaussian1D f;
  std::vector<double> n_values, errors;
  for (std::uint64_t n : log_grid(10, 1000, 5)) {
    n_values.push_back(static_cast<double>(n));
    errors.push_back(std::abs(rule(f, n) - f.reference()));
  }
  return log_log_slope(n_values, errors);
}

TEST_F(KnownBugsTest, TrapezoidWithFullEndWeightsIsRejected) {
  constexpr double k_slope_tolerance = 0.1;
  const SlopeEstimate right = trapezoid_slope(
      [](const Gaussian1D& f, std::uint64_t n) { return trapezoid(f, f.domain, n); });
  const SlopeEstimate wrong = trapezoid_slope(trapezoid_with_full_end_weights);
  EXPECT_NEAR(right.slope, -2.0, k_slope_tolerance);
  EXPECT_GT(std::abs(wrong.slope + 2.0), k_slope_tolerance) << "slope " << wrong.slope;
  EXPECT_NEAR(wrong.slope, -1.0, k_slope_tolerance);
}

}  // namespace
