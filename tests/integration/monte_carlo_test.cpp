// The plain Monte Carlo estimator, deterministically: where it samples, what it returns for
// integrands without variance, how its standard error is formed, and that the z-test the
// statistical checks use rejects the known-wrong estimators of monte_carlo_known_bugs.hpp. Its mean and variance against
// closed forms are statistical checks: tests/integration/monte_carlo_checks.cpp.

#include "integration/monte_carlo.hpp"

#include <cmath>
#include <span>

#include <gtest/gtest.h>

#include "integration/integrands.hpp"
#include "integration/statistics.hpp"
#include "integration/monte_carlo_known_bugs.hpp"
#include "stats/hypothesis.hpp"

namespace {

using mcrt::Box;
using mcrt::Rng;
using mcrt::Segment;

Box test_box() {
  Box box;
  box.dims = 3;
  box.lower = {0.0, -1.0, 2.0};
  box.upper = {2.0, 3.0, 2.5};
  return box;  // volume 2 * 4 * 0.5 = 4
}

TEST(MonteCarlo, ConstantIntegrandIsExactWithZeroStandardError) {
  // f = 0.75: every term is the same, sum = 0.75 N exactly, so F_N = vol * 0.75 with no
  // round-off at all and s^2 = 0.
  Rng rng(7, 0);
  const auto result =
      mcrt::monte_carlo([](std::span<const double>) { return 0.75; }, test_box(), 1000, rng);
  EXPECT_EQ(result.estimate, 3.0);
  EXPECT_EQ(result.standard_error, 0.0);
  Rng rng1(7, 1);
  EXPECT_EQ(mcrt::monte_carlo([](double) { return 0.75; }, Segment{-1.0, 3.0}, 1000, rng1).estimate,
            3.0);
}

TEST(MonteCarlo, SamplesStayInsideTheBoxAndEachIsEvaluatedOnce) {
  const Box box = test_box();
  int calls = 0, outside = 0;
  const auto f = [&](std::span<const double> x) {
    ++calls;
    EXPECT_EQ(x.size(), 3u);
    for (int i = 0; i < 3; ++i) outside += x[i] < box.lower[i] || x[i] >= box.upper[i];
    return 1.0;
  };
  Rng rng(3, 5);
  mcrt::monte_carlo(f, box, 5000, rng);
  EXPECT_EQ(calls, 5000);
  EXPECT_EQ(outside, 0);
}

TEST(MonteCarlo, SameStreamSameEstimateOtherStreamDifferent) {
  const mcrt::GaussianProduct g{4};
  Rng a(11, 2), b(11, 2), c(11, 3);
  const double first = mcrt::monte_carlo(g, g.domain(), 200, a).estimate;
  EXPECT_EQ(first, mcrt::monte_carlo(g, g.domain(), 200, b).estimate);
  EXPECT_NE(first, mcrt::monte_carlo(g, g.domain(), 200, c).estimate);
}

TEST(MonteCarlo, OneDimensionalBoxMatchesSegment) {
  // Both draw one uniform per sample and map it the same way: identical estimates.
  const mcrt::Gaussian1D g;
  const auto on_box = [&](std::span<const double> x) { return g(x[0]); };
  Rng a(5, 9), b(5, 9);
  EXPECT_EQ(mcrt::monte_carlo(g, g.domain, 777, a).estimate,
            mcrt::monte_carlo(on_box, Box::cube(1, 0.0, 1.0), 777, b).estimate);
}

TEST(MonteCarlo, EstimateAndStandardErrorFromTheSameSamples) {
  // Replays the estimator's stream by hand: F_N = vol * mean of f(X_i) and its standard error
  // vol * s / sqrt(N) with the unbiased s^2 (Welford here, one-pass sums there: they agree
  // to round-off, 1e-12 relative).
  const mcrt::XCosX f;
  const std::uint64_t n = 4096;
  Rng rng(21, 4), replay(21, 4);
  const auto result = mcrt::monte_carlo(f, f.domain, n, rng);
  mcrt::RunningStats stats;
  for (std::uint64_t i = 0; i < n; ++i)
    stats.add(f(f.domain.lower + replay.uniform() * f.domain.length()));
  const double vol = f.domain.length();
  EXPECT_NEAR(result.estimate, vol * stats.mean(), 1e-12 * std::abs(vol * stats.mean()));
  EXPECT_NEAR(result.standard_error, vol * stats.standard_error(),
              1e-12 * vol * stats.standard_error());
}

TEST(MonteCarlo, VarianceClosedForm) {
  // The indicator of half of a box: I = J = vol/2, so V[F_N] = (vol^2/2 - vol^2/4)/N = vol^2/(4N).
  EXPECT_DOUBLE_EQ(mcrt::monte_carlo_variance(4.0, 2.0, 2.0, 8), 16.0 / 32.0);
  // A constant has no variance: vol J = vol * c^2 vol = I^2.
  EXPECT_DOUBLE_EQ(mcrt::monte_carlo_variance(2.0, 2.0 * 3.0, 2.0 * 9.0, 10), 0.0);
}

// The z-test of the statistical checks, run on estimators that are wrong by mistakes a
// student makes, at a fixed seed: they must be rejected at the checks' alpha = 1e-4. With
// 2e5 samples the standard error of the x^3 estimate is ~0.01, against biases of 2 (no
// volume factor) and 0.12 (samples only from [0, 1.98)).
TEST(MonteCarlo, ZTestRejectsKnownWrongEstimators) {
  const mcrt::Cubic cubic;
  const std::uint64_t n = 200000;
  const double standard_error =
      std::sqrt(mcrt::monte_carlo_variance(cubic.domain.length(), cubic.reference(),
                                           cubic.integral_of_square(), n));
  Rng rng(42, 0), rng_short(42, 1), rng_right(42, 2);
  const auto p = [&](double estimate) {
    return mcrt::testing::z_test_p_value(estimate, cubic.reference(), standard_error);
  };
  EXPECT_LT(p(mcrt::testing::monte_carlo_without_volume(cubic, cubic.domain, n, rng)), 1e-4);
  EXPECT_LT(p(mcrt::testing::monte_carlo_on_short_interval(cubic, cubic.domain, n, rng_short)),
            1e-4);
  // The right estimator passes at this seed (its own false-failure rate is 1e-4).
  EXPECT_GE(p(mcrt::monte_carlo(cubic, cubic.domain, n, rng_right).estimate), 1e-4);
}

}  // namespace
