// Known bugs are caught. Each test below keeps a deliberately wrong variant of a piece of the
// core, written here and nowhere else, and asserts that the statistical test the real piece
// passes in the suite rejects it: the same test function, the same sample sizes, the same seed
// (k_suite_seed, or the suite's seed offset for that check) and the same alpha. The real piece
// is run beside it, so a test that rejects everything would fail here too.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "checks/furnace_paths.hpp"
#include "checks/small_trials.hpp"
#include "integration/integrands.hpp"
#include "integration/log_grid.hpp"
#include "integration/quadrature.hpp"
#include "render/path_tracer.hpp"
#include "sampling/sampling.hpp"
#include "stats/check.hpp"
#include "stats/convergence.hpp"
#include "stats/report.hpp"
#include "stats/sampler_tests.hpp"

using namespace mcrt;
using namespace mcrt::stats;

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

// Bug: r = u instead of sqrt(u), so points crowd the centre (the density in r^2 is
// 1 / (2 sqrt(r^2)) instead of 1).
Vec2 disk_with_radius_u(Vec2 u) {
  const double r = u.x;
  const double phi = k_two_pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi)};
}

TEST_F(KnownBugsTest, DiskSamplerWithRadiusUIsRejected) {
  EXPECT_GE(disk_sampler_p_value(sample_uniform_disk, disk_pdf, k_seed, k_disk_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(disk_sampler_p_value(disk_with_radius_u, disk_pdf, k_seed, k_disk_stream, "wrong"),
            k_sampler_alpha);
}

// Bug: the uniform hemisphere sampler's pdf claims 1/pi per steradian, twice 1/(2 pi): every
// estimate divided by it would come out half as large.
double hemisphere_pdf_one_over_pi(const Vec3&) { return k_inv_pi; }

TEST_F(KnownBugsTest, HemisphereSamplerWhosePdfClaimsOneOverPiIsRejected) {
  EXPECT_GE(hemisphere_sampler_p_value(sample_uniform_hemisphere, uniform_hemisphere_pdf_at,
                                       k_seed, k_uniform_hemisphere_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(hemisphere_sampler_p_value(sample_uniform_hemisphere, hemisphere_pdf_one_over_pi,
                                       k_seed, k_uniform_hemisphere_stream, "wrong"),
            k_sampler_alpha);
}

// Bug: the cosine-weighted sampler's pdf has an extra factor 2, 2 cos(theta) / pi (the
// normalisation of the cosine lobe worked out over the whole sphere's 2 pi instead of pi).
double cosine_pdf_times_two(const Vec3& w) { return 2.0 * w.z * k_inv_pi; }

TEST_F(KnownBugsTest, CosineSamplerWithAnExtraFactorTwoIsRejected) {
  EXPECT_GE(hemisphere_sampler_p_value(sample_cosine_hemisphere, cosine_hemisphere_pdf_at,
                                       k_seed, k_cosine_hemisphere_stream, "right"),
            k_sampler_alpha);
  EXPECT_LT(hemisphere_sampler_p_value(sample_cosine_hemisphere, cosine_pdf_times_two, k_seed,
                                       k_cosine_hemisphere_stream, "wrong"),
            k_sampler_alpha);
}

// The failure report of the r = u disk shows where it is wrong: far too many samples in the
// innermost ring (r^2 < 1/11 holds 30% of them, not 9%) and too few in the outermost.
TEST_F(KnownBugsTest, FailureReportPointsAtTheWrongRadius) {
  const Binning<Vec2> binning = sampler_disk_binning();
  const ChiSquareResult r = chi_square_sampler_test(disk_with_radius_u, disk_pdf, binning,
                                                    k_seed, k_sampler_samples, k_disk_stream);
  double inner_observed = 0.0, inner_expected = 0.0, outer_observed = 0.0, outer_expected = 0.0;
  for (const CellCount& c : r.cells) {
    if (c.u_index == 0) inner_observed += c.observed, inner_expected += c.expected;
    if (c.u_index == binning.u_cells - 1) outer_observed += c.observed, outer_expected += c.expected;
  }
  // sqrt(1/11) = 0.3015 of the samples; 1e5 samples put the fraction within 0.005 (3.5 sigma).
  EXPECT_NEAR(inner_observed / k_sampler_samples, std::sqrt(1.0 / 11.0), 0.005);
  EXPECT_NEAR(inner_expected / k_sampler_samples, 1.0 / 11.0, 1e-9);
  EXPECT_LT(outer_observed, 0.6 * outer_expected);  // 1 - sqrt(10/11) = 0.047 vs 0.091
  const auto csv = write_chi_square_report(failure_report_root() / "known_bug_disk_r_equals_u",
                                           "known_bug_disk_r_equals_u", r, binning);
  EXPECT_TRUE(std::filesystem::exists(csv));
}

// ---- The path tracer: the furnace mean (tests/checks/furnace_paths.hpp, alpha 1e-4) --------

// Bug: the path weight misses cos(theta_i): beta *= f_r / p instead of f_r cos / p. With
// uniform directions each bounce then weighs 2a instead of a on average.
Color path_radiance_without_cosine(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                   RayCount& count) {
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    radiance += beta * scene.material(*hit).emission;
    if (bounce == max_depth) break;
    const Vec3 wi = Frame(hit->normal).to_world(sample_uniform_hemisphere(rng.uniform2()));
    beta *= scene.material(*hit).brdf() / uniform_hemisphere_pdf();  // the missing cosine
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
}

TEST_F(KnownBugsTest, PathWeightMissingTheCosineIsRejected) {
  // As the check path_tracer_furnace_mean_a05_k4: a = 0.5, Le = 1, k = 4, 40000 paths, seed
  // offset 2 (tests/checks/path_tracer_checks.cpp).
  const mcrt::testing::FurnaceSetup setup{0.5, 1.0, 4};
  constexpr int k_paths = 40000;
  const auto p = [&](auto tracer) {
    return mcrt::testing::furnace_mean_p_value(
        setup, mcrt::testing::furnace_samples(setup, k_paths, k_seed, 2, tracer));
  };
  EXPECT_GE(p(mcrt::testing::chapter_path_tracer), 1e-4);
  EXPECT_LT(p(path_radiance_without_cosine), 1e-4);
}

// ---- Trials of a small estimate (tests/checks/small_trials.hpp, alpha 1e-4) ----------------

// Bug: the sum divided by N - 1 instead of N (the sample variance's denominator, misplaced):
// E = I N / (N - 1), a bias of I / 15 at N = 16.
double estimate_dividing_by_n_minus_one(std::uint64_t n, Rng& rng) {
  const double f_n = checks::gaussian_estimate(n, rng);  // sum / N
  return f_n * static_cast<double>(n) / static_cast<double>(n - 1);
}

TEST_F(KnownBugsTest, EstimatorDividingByNMinusOneIsRejected) {
  EXPECT_GE(checks::small_trials_p_value(checks::gaussian_estimate, k_seed), 1e-4);
  EXPECT_LT(checks::small_trials_p_value(estimate_dividing_by_n_minus_one, k_seed), 1e-4);
}

// Bug: every trial starts the same generator stream, Rng(seed, 0), so all trials are the same
// numbers: the spread between trials, the very thing a study measures, is zero.
struct SameStreamTrials {
  template <class Estimator>
  std::vector<double> operator()(const Estimator& estimate, std::uint64_t trials,
                                 std::uint64_t seed) const {
    std::vector<double> estimates(trials);
    for (std::uint64_t t = 0; t < trials; ++t) {
      Rng rng(seed, 0);  // should be Rng(seed, t)
      estimates[t] = estimate(rng);
    }
    return estimates;
  }
};

TEST_F(KnownBugsTest, GeneratorStreamReusedAcrossTrialsIsRejected) {
  EXPECT_LT(checks::small_trials_p_value(checks::gaussian_estimate, k_seed, SameStreamTrials{}),
            1e-4);
}

// ---- The trapezoid rule: its n^-2 rate ------------------------------------------------------

// Bug: full weights at the ends, h sum_{i=0..n-1} f(x_i): off by h (f(a) + f(b)) / 2, which
// only falls as n^-1.
double trapezoid_with_full_end_weights(const Gaussian1D& f, std::uint64_t n) {
  const double h = f.domain.length() / static_cast<double>(n - 1);
  double sum = 0.0;
  for (std::uint64_t i = 0; i < n; ++i) sum += f(grid_point(f.domain.lower, f.domain.upper, i, n));
  return h * sum;
}

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
  const SlopeEstimate right =
      trapezoid_slope([](const Gaussian1D& f, std::uint64_t n) { return trapezoid(f, f.domain, n); });
  const SlopeEstimate wrong = trapezoid_slope(trapezoid_with_full_end_weights);
  EXPECT_NEAR(right.slope, -2.0, k_slope_tolerance);
  EXPECT_GT(std::abs(wrong.slope + 2.0), k_slope_tolerance) << "slope " << wrong.slope;
  EXPECT_NEAR(wrong.slope, -1.0, k_slope_tolerance);
}

}  // namespace
