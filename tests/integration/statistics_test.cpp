// The statistics the tests rest on: common/integration/statistics.hpp (running moments, least squares)
// and the test toolkit of tests/stats/ (hypothesis tests, binnings, chi-square, slopes),
// checked on fixed inputs against values worked out by hand or tabulated.

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "integration/statistics.hpp"
#include "stats/binning.hpp"
#include "stats/chi_square.hpp"
#include "stats/convergence.hpp"
#include "stats/hypothesis.hpp"
#include "stats/report.hpp"
#include "stats/trials.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

// Tabulated quantiles are given to 6-7 digits; 1e-5 is the precision of the tables.
constexpr double k_table_tol = 1e-5;

// ---- common/integration/statistics.hpp ----------------------------------------------------------------

TEST(RunningStatsTest, MeanAndVarianceOfAKnownSample) {
  RunningStats s;
  for (double x : {2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0}) s.add(x);
  EXPECT_EQ(s.count(), 8u);
  EXPECT_DOUBLE_EQ(s.mean(), 5.0);
  EXPECT_DOUBLE_EQ(s.variance(), 32.0 / 7.0);  // sum of squared deviations 32, over n - 1
  EXPECT_DOUBLE_EQ(s.standard_error(), std::sqrt(32.0 / 7.0 / 8.0));
}

TEST(RunningStatsTest, FewerThanTwoValuesHaveZeroVariance) {
  RunningStats s;
  EXPECT_EQ(s.variance(), 0.0);
  EXPECT_EQ(s.standard_error(), 0.0);
  s.add(3.0);
  EXPECT_EQ(s.mean(), 3.0);
  EXPECT_EQ(s.variance(), 0.0);
}

TEST(RunningStatsTest, StaysAccurateFarFromZero) {
  // The naive sum-of-squares formula loses every digit here (1e18 + ...); Welford does not.
  RunningStats s;
  for (double x : {4.0, 7.0, 13.0, 16.0}) s.add(1e9 + x);
  EXPECT_NEAR(s.variance(), 30.0, 1e-6);  // round-off of 1e9 + x is 1e-7
}

TEST(RunningStatsTest, MergingEqualsAddingEverything) {
  RunningStats all, left, right;
  for (int i = 0; i < 20; ++i) {
    const double x = std::sin(i * 1.7) * 10.0 + i;
    all.add(x);
    (i < 7 ? left : right).add(x);
  }
  left.merge(right);
  left.merge(RunningStats{});  // merging nothing changes nothing
  EXPECT_EQ(left.count(), all.count());
  EXPECT_NEAR(left.mean(), all.mean(), 1e-12);
  EXPECT_NEAR(left.variance(), all.variance(), 1e-10);
}

TEST(FitLineTest, WorkedExample) {
  // x = 1..4, y = 2, 3, 5, 6: sxx = 5, sxy = 7, slope 1.4, intercept 0.5; residuals
  // 0.1, -0.3, 0.3, -0.1 sum to 0.2 squared, so se = sqrt(0.2 / 2 / 5).
  const std::array<double, 4> x{1, 2, 3, 4}, y{2, 3, 5, 6};
  const LineFit fit = fit_line(x, y);
  EXPECT_NEAR(fit.slope, 1.4, 1e-12);
  EXPECT_NEAR(fit.intercept, 0.5, 1e-12);
  EXPECT_NEAR(fit.slope_standard_error, std::sqrt(0.02), 1e-12);
}

TEST(FitLineTest, LogLogSlopeOfAPowerLaw) {
  const std::array<double, 4> n{10, 100, 1000, 10000};
  std::array<double, 4> error{};
  for (std::size_t i = 0; i < n.size(); ++i) error[i] = 3.0 / std::sqrt(n[i]);
  const LineFit fit = fit_log_log(n, error);
  EXPECT_NEAR(fit.slope, -0.5, 1e-12);
  EXPECT_NEAR(fit.intercept, std::log(3.0), 1e-12);
  EXPECT_NEAR(fit.slope_standard_error, 0.0, 1e-12);
}

// ---- tests/stats/hypothesis ---------------------------------------------------------------

TEST(HypothesisTest, ZAndTTestsAtTabulatedCriticalValues) {
  EXPECT_NEAR(z_test_p_value(1.959964, 0.0, 1.0), 0.05, k_table_tol);
  EXPECT_NEAR(z_test_p_value(10.0 - 2.0 * 2.575829, 10.0, 2.0), 0.01, k_table_tol);
  // t with 9 dof: 2.262157 at 0.975. Mean 1 + t s / sqrt(n) with s^2 = 4, n = 10.
  EXPECT_NEAR(t_test_p_value(1.0 + 2.262157 * 2.0 / std::sqrt(10.0), 4.0, 10, 1.0), 0.05,
              k_table_tol);
  EXPECT_EQ(z_test_p_value(1.0, 1.0, 0.0), 1.0);  // no spread: equal or impossible
  EXPECT_EQ(z_test_p_value(1.5, 1.0, 0.0), 0.0);
}

TEST(HypothesisTest, VarianceTestIsTwoSided) {
  // chi^2 with 10 dof: 20.48318 at 0.975 and 3.246973 at 0.025; n = 11 values.
  EXPECT_NEAR(variance_test_p_value(2.048318, 11, 1.0), 0.05, k_table_tol);
  EXPECT_NEAR(variance_test_p_value(0.3246973, 11, 1.0), 0.05, k_table_tol);
  EXPECT_EQ(variance_test_p_value(0.0, 11, 1.0), 0.0);    // identical values: caught at once
  EXPECT_EQ(variance_test_p_value(0.0, 4000, 1.0), 0.0);  // ... for any number of them
}

TEST(HypothesisTest, VarianceZTestUsesTheFourthMoment) {
  // Uniform values: sigma^2 = 1/12, mu4 = 1/80, so Var[s^2] = (1/80 - (n-3)/(n-1)/144) / n.
  const std::uint64_t n = 100000;
  const double sd = std::sqrt((1.0 / 80.0 - (n - 3.0) / (n - 1.0) / 144.0) / n);
  EXPECT_NEAR(variance_z_test_p_value(1.0 / 12.0 + 1.959964 * sd, n, 1.0 / 12.0, 1.0 / 80.0), 0.05,
              k_table_tol);
  // The uniform's light tails make s^2 steadier than for normal values (mu4 = 3 sigma^4):
  // the same deviation is more significant.
  const double normal_sd = std::sqrt(2.0 / (n - 1.0)) / 12.0;
  EXPECT_LT(sd, normal_sd);
}

TEST(HypothesisTest, DistributionFunctionsAtTabulatedValues) {
  EXPECT_NEAR(chi_square_upper_tail(3.841459, 1.0), 0.05, k_table_tol);
  EXPECT_NEAR(chi_square_upper_tail(124.3421, 100.0), 0.05, k_table_tol);
  EXPECT_NEAR(normal_quantile(0.975), 1.959964, k_table_tol);
  EXPECT_NEAR(student_t_quantile(0.975, 9.0), 2.262157, k_table_tol);
}

TEST(HypothesisTest, SidakCorrection) {
  EXPECT_NEAR(sidak_alpha(0.05, 1), 0.05, 1e-15);
  EXPECT_NEAR(sidak_alpha(0.05, 10), 1.0 - std::pow(0.95, 0.1), 1e-15);
  // The adjusted p-value rejects at alpha exactly when the smallest p is below sidak_alpha.
  for (int m : {1, 3, 10}) EXPECT_NEAR(sidak_p_value(sidak_alpha(1e-4, m), m), 1e-4, 1e-15);
  const std::array<double, 3> p{0.5, 0.01, 0.9};
  EXPECT_NEAR(sidak_p_value(p), 1.0 - std::pow(0.99, 3), 1e-15);
  EXPECT_NEAR(sidak_p_value(1e-12, 5), 5e-12, 1e-22);  // expm1 keeps tiny p exact
}

TEST(HypothesisTest, ExactBinomialIntervalAndTest) {
  // No successes: the upper end solves (1 - p)^n = tail, i.e. 1 - tail^(1/n).
  const ConfidenceInterval none = binomial_confidence_interval(0, 400, 0.99);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 1.0 - std::pow(0.005, 1.0 / 400.0), 1e-10);
  const ConfidenceInterval all = binomial_confidence_interval(50, 50, 0.95);
  EXPECT_NEAR(all.low, std::pow(0.025, 1.0 / 50.0), 1e-10);
  EXPECT_EQ(all.high, 1.0);
  const ConfidenceInterval some = binomial_confidence_interval(20, 400, 0.99);
  EXPECT_TRUE(some.contains(0.05));
  EXPECT_FALSE(some.contains(0.1));
  // Binomial(10, 1/2): P(X = 0) = 1/1024, doubled for two sides.
  EXPECT_NEAR(binomial_test_p_value(0, 10, 0.5), 2.0 / 1024.0, 1e-15);
  EXPECT_NEAR(binomial_test_p_value(10, 10, 0.5), 2.0 / 1024.0, 1e-15);
  EXPECT_EQ(binomial_test_p_value(5, 10, 0.5), 1.0);
}

TEST(HypothesisTest, KolmogorovSmirnovUniformity) {
  // Evenly spread values (i + 1/2)/n are off the CDF by exactly 1/(2n) at every step.
  std::vector<double> even(100);
  for (std::size_t i = 0; i < even.size(); ++i) even[i] = (static_cast<double>(i) + 0.5) / 100.0;
  EXPECT_NEAR(uniformity_ks_statistic(even), 0.005, 1e-12);
  EXPECT_GT(ks_p_value(0.005, 100), 0.999);
  // All values below 1/2: D = 1/2, far in the tail.
  const std::vector<double> low(100, 0.25);
  EXPECT_NEAR(uniformity_ks_statistic(low), 0.75, 1e-12);
  EXPECT_LT(ks_p_value(0.75, 100), 1e-20);
  // Asymptotically P(sqrt(n) D > 1.3581) = 0.05 (the tabulated 5% point); at n = 1e8 the
  // finite-n correction is below 1e-5.
  EXPECT_NEAR(ks_p_value(1.358099 / 1e4, 100000000), 0.05, 1e-4);
}

// ---- tests/stats/binning ------------------------------------------------------------------

template <class Point>
void expect_cells_round_trip(const Binning<Point>& b) {
  for (int j = 0; j < b.v_cells; ++j)
    for (int i = 0; i < b.u_cells; ++i) {
      const Point centre =
          b.point_at(b.u_low(i) + 0.5 * b.u_width(), b.v_low(j) + 0.5 * b.v_width());
      EXPECT_EQ(b.cell_of(centre), j * b.u_cells + i) << b.name << " cell " << i << "," << j;
    }
}

TEST(BinningTest, CellCentresMapBackToTheirCells) {
  expect_cells_round_trip(square_binning(5));
  expect_cells_round_trip(disk_binning(7, 9));
  expect_cells_round_trip(hemisphere_binning(9, 5));
}

TEST(BinningTest, PointsOutsideTheDomainHaveNoCell) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(square_binning(3).cell_of(Vec2(1.01, 0.0)), -1);
  EXPECT_EQ(square_binning(3).cell_of(Vec2(nan, 0.0)), -1);
  EXPECT_EQ(disk_binning(3, 3).cell_of(Vec2(0.8, 0.7)), -1);  // r^2 = 1.13
  EXPECT_EQ(disk_binning(3, 3).cell_of(Vec2(nan, nan)), -1);
  EXPECT_EQ(hemisphere_binning(3, 3).cell_of(Vec3(0.0, 0.6, -0.8)), -1);  // below the horizon
  EXPECT_EQ(hemisphere_binning(3, 3).cell_of(Vec3(0.0, 0.0, 0.5)), -1);   // not unit length
  // The boundary itself belongs to the domain: the rim of the disk, the horizon, the corners.
  EXPECT_GE(disk_binning(3, 3).cell_of(Vec2(1.0, 0.0)), 0);
  EXPECT_GE(hemisphere_binning(3, 3).cell_of(Vec3(1.0, 0.0, 0.0)), 0);
  EXPECT_EQ(square_binning(3).cell_of(Vec2(1.0, 1.0)), 8);
}

TEST(BinningTest, ConstantOneIntegratesToTheDomainsMeasure) {
  // The Jacobians: the square's area 4, the disk's pi, the hemisphere's 2 pi steradians.
  // Constant integrands are integrated exactly, up to round-off.
  const auto one = [](const auto&) { return 1.0; };
  EXPECT_NEAR(pdf_integral(one, square_binning(4)), 4.0, 1e-12);
  EXPECT_NEAR(pdf_integral(one, disk_binning(4, 5)), k_pi, 1e-12);
  EXPECT_NEAR(pdf_integral(one, hemisphere_binning(5, 3)), k_two_pi, 1e-12);
}

TEST(BinningTest, CellProbabilitiesOfANonUniformPdf) {
  // pdf = 2 r^2 / pi on the disk: a ring s0 <= r^2 <= s1 over one of m sectors has probability
  // integral of (2/pi) s * (1/2) ds dphi = (s1^2 - s0^2) / m. The quadrature is exact for this
  // polynomial in s, so the tolerance is round-off.
  const Binning<Vec2> b = disk_binning(4, 3);
  const auto pdf = [](const Vec2& p) { return 2.0 * glm::dot(p, p) / k_pi; };
  const std::vector<double> probability = cell_probabilities(pdf, b);
  for (int j = 0; j < b.v_cells; ++j)
    for (int i = 0; i < b.u_cells; ++i) {
      const double s0 = b.u_low(i), s1 = s0 + b.u_width();
      EXPECT_NEAR(probability[static_cast<std::size_t>(j * b.u_cells + i)],
                  (s1 * s1 - s0 * s0) / b.v_cells, 1e-12);
    }
}

// ---- tests/stats/chi_square ---------------------------------------------------------------

std::vector<CellCount> cells_of(std::initializer_list<double> observed,
                                std::initializer_list<double> expected) {
  std::vector<CellCount> cells;
  auto e = expected.begin();
  int i = 0;
  for (double o : observed) cells.push_back({i++, 0, o, *e++});
  return cells;
}

TEST(ChiSquareTest, PearsonStatisticOfAWorkedExample) {
  // (12 - 10)^2/10 + (8 - 10)^2/10 = 0.8 on 3 degrees of freedom.
  const ChiSquareResult r = chi_square_test(cells_of({12, 8, 10, 10}, {10, 10, 10, 10}), 0);
  EXPECT_NEAR(r.statistic, 0.8, 1e-12);
  EXPECT_EQ(r.dof, 3.0);
  EXPECT_NEAR(r.p_value, chi_square_upper_tail(0.8, 3.0), 1e-15);
  EXPECT_EQ(r.pooled_cells, 0);
  const ChiSquareResult perfect = chi_square_test(cells_of({7, 9}, {7, 9}), 0);
  EXPECT_EQ(perfect.statistic, 0.0);
  EXPECT_EQ(perfect.p_value, 1.0);
}

TEST(ChiSquareTest, SmallCellsArePooled) {
  // Expected 1, 2, 3 pool into one cell of 6 >= 5: three bins, two degrees of freedom.
  const ChiSquareResult r = chi_square_test(cells_of({0, 4, 2, 20, 20}, {1, 2, 3, 20, 20}), 0);
  EXPECT_EQ(r.pooled_cells, 3);
  EXPECT_EQ(r.dof, 2.0);
  EXPECT_NEAR(r.statistic, 0.0, 1e-12);  // the pool has 6 observed for 6 expected
  // A pool still below 5 (1 + 2) takes in the next smallest cell: two bins, one dof.
  const ChiSquareResult merged = chi_square_test(cells_of({3, 0, 25, 21}, {1, 2, 20, 21}), 0);
  EXPECT_EQ(merged.pooled_cells, 2);
  EXPECT_EQ(merged.dof, 1.0);
  EXPECT_NEAR(merged.statistic, 25.0 / 23.0, 1e-12);  // (28 - 23)^2 / 23 + (21 - 21)^2 / 21
}

TEST(ChiSquareTest, ImpossibleSamplesFailAtOnce) {
  const ChiSquareResult zero_cell = chi_square_test(cells_of({1, 50, 49}, {0, 50, 50}), 0);
  EXPECT_EQ(zero_cell.p_value, 0.0);
  EXPECT_NE(zero_cell.immediate_failure.find("pdf is zero"), std::string::npos);
  const ChiSquareResult outside = chi_square_test(cells_of({50, 49}, {50, 50}), 1);
  EXPECT_EQ(outside.p_value, 0.0);
  EXPECT_NE(outside.immediate_failure.find("outside"), std::string::npos);
  // An empty zero-expected cell is no evidence either way.
  EXPECT_EQ(chi_square_test(cells_of({0, 50, 50}, {0, 50, 50}), 0).dof, 1.0);
}

TEST(ChiSquareTest, TooFewSamplesForTheBinningIsAnError) {
  EXPECT_THROW(chi_square_test(cells_of({1, 1, 1}, {1, 1, 1}), 0), std::invalid_argument);
}

TEST(ChiSquareTest, FailureReportHasOneRowPerCellAndAPlotScript) {
  const Binning<Vec2> b = square_binning(3);
  const auto uniform = [](const Vec2&) { return 0.25; };
  // The left column only: a sampler that never goes right of x = -1/3.
  const auto left_only = [](Vec2 u) { return Vec2(-1.0 + 2.0 / 3.0 * u.x, 2.0 * u.y - 1.0); };
  const ChiSquareResult r = chi_square_sampler_test(left_only, uniform, b, 7, 900);
  EXPECT_LT(r.p_value, 1e-100);
  const auto dir = failure_report_root() / "statistics_test_report";
  const auto csv_path = write_chi_square_report(dir, "left_only", r, b);
  std::ifstream csv(csv_path);
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "u_index,v_index,u_low,u_high,v_low,v_high,observed,expected,residual");
  double observed = 0.0, expected = 0.0;
  int rows = 0;
  while (std::getline(csv, line)) {
    std::stringstream row(line);
    std::array<double, 9> v{};
    for (double& x : v) {
      std::string field;
      std::getline(row, field, ',');
      x = std::stod(field);
    }
    observed += v[6];
    expected += v[7];
    if (v[0] == 0)
      EXPECT_GT(v[6], 0.0);  // the left column has every sample
    else
      EXPECT_EQ(v[6], 0.0);
    ++rows;
  }
  EXPECT_EQ(rows, 9);
  EXPECT_EQ(observed, 900.0);
  EXPECT_NEAR(expected, 900.0, 1e-9);
  EXPECT_TRUE(std::filesystem::exists(dir / "left_only.gp"));
}

// ---- tests/stats/convergence and trials ---------------------------------------------------

TEST(ConvergenceTest, SlopeIntervalCoversTheTrueSlopeOfNoisyData) {
  // error = n^-1/2 times a fixed wobble exp(+-0.05): the fitted slope is near -1/2, the
  // interval is slope -+ t_{0.995, 5} se and contains -1/2; a slope of -1 is rejected.
  const std::array<double, 7> n{10, 30, 100, 300, 1000, 3000, 10000};
  const std::array<double, 7> wobble{0.05, -0.05, 0.03, -0.02, 0.05, -0.04, 0.01};
  std::array<double, 7> error{};
  for (std::size_t i = 0; i < n.size(); ++i) error[i] = std::exp(wobble[i]) / std::sqrt(n[i]);
  const SlopeEstimate s = log_log_slope(n, error, 0.99);
  EXPECT_NEAR(s.slope, -0.5, 0.03);
  EXPECT_EQ(s.dof, 5.0);
  EXPECT_NEAR(s.confidence.high - s.slope, student_t_quantile(0.995, 5.0) * s.standard_error,
              1e-12);
  EXPECT_TRUE(s.confidence.contains(-0.5));
  EXPECT_GT(slope_p_value(s, -0.5), 0.01);
  EXPECT_LT(slope_p_value(s, -1.0), 1e-6);
  EXPECT_THROW(log_log_slope(std::span(n).first(2), std::span(error).first(2)),
               std::invalid_argument);
}

TEST(TrialsTest, RunTrialsUsesOneStreamPerTrialWhateverTheThreads) {
  const auto first_uniform = [](Rng& rng) { return rng.uniform(); };
  const std::vector<double> one = run_trials(first_uniform, 64, 5, 1);
  const std::vector<double> two = run_trials(first_uniform, 64, 5, 2);
  EXPECT_EQ(one, two);
  for (std::size_t t = 0; t < one.size(); ++t) EXPECT_EQ(one[t], Rng(5, t).uniform());
}

TEST(TrialsTest, IdenticalTrialsAreRejected) {
  const std::vector<double> same(100, 0.5);
  EXPECT_EQ(trials_p_value(same, 0.5, 0.01), 0.0);  // variance 0 against 0.01
}

}  // namespace

namespace {

// Estimates 1, 2, 6 of the exact value 2: mean 3, bias 1, s^2 = ((-2)^2 + (-1)^2 + 3^2) / 2
// = 7, rmse = sqrt((1 + 0 + 16) / 3); and rmse^2 = bias^2 + (T-1)/T s^2 = 1 + 14/3 = 17/3.
TEST(ErrorStatsTest, MeanBiasSpreadAndRmseOfRepeatedEstimates) {
  mcrt::ErrorStats errors(2.0);
  for (double estimate : {1.0, 2.0, 6.0}) errors.add(estimate);
  EXPECT_EQ(errors.count(), 3u);
  EXPECT_DOUBLE_EQ(errors.mean(), 3.0);
  EXPECT_DOUBLE_EQ(errors.bias(), 1.0);
  EXPECT_DOUBLE_EQ(errors.stddev(), std::sqrt(7.0));
  EXPECT_DOUBLE_EQ(errors.rmse(), std::sqrt(17.0 / 3.0));
  EXPECT_DOUBLE_EQ(errors.rmse() * errors.rmse(),
                   errors.bias() * errors.bias() + 2.0 / 3.0 * errors.stddev() * errors.stddev());
}

TEST(MedianTest, OddAndEvenCounts) {
  EXPECT_EQ(mcrt::median({3.0, 1.0, 2.0}), 2.0);
  EXPECT_EQ(mcrt::median({4.0, 1.0, 3.0, 2.0}), 2.5);
  EXPECT_EQ(mcrt::median({5.0}), 5.0);
}

}  // namespace
