// Plain Monte Carlo against closed forms: F_N = vol/N sum f(X_i) has E[F_N] = I and
// V[F_N] = (vol J - I^2) / N (J = integral of f^2), so its rms error falls as N^(-1/2).

#include <cmath>
#include <vector>

#include <boost/math/special_functions/trigamma.hpp>

#include "core/rng.hpp"
#include "integration/integrands.hpp"
#include "integration/log_grid.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/statistics.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"

namespace {

// Unbiasedness: the mean of T independent F_N is compared with I by a z-test whose standard
// error sqrt(V[F_N] / T) comes from the closed form, not from the data. The mean is an
// average of T N >= 1e5 bounded values, normal to far better than the test needs.
// False-failure rate alpha = 1e-4.
template <class Integrand, class Domain>
double unbiased_p_value(const Integrand& f, const Domain& domain, double volume, std::uint64_t seed,
                        int trials, std::uint64_t n) {
  mcrt::RunningStats estimates;
  for (int t = 0; t < trials; ++t) {
    mcrt::Rng rng(seed, static_cast<std::uint64_t>(t));
    estimates.add(mcrt::monte_carlo(f, domain, n, rng).estimate);
  }
  const double v_f_n = mcrt::monte_carlo_variance(volume, f.reference(), f.integral_of_square(), n);
  return mcrt::testing::z_test_p_value(estimates.mean(), f.reference(), std::sqrt(v_f_n / trials));
}

// The slide's x^3 on [0, 2]: I = 4, J = 2^7/7. 200 trials of N = 1000.
MCRT_STATISTICAL_CHECK(monte_carlo_unbiased_on_cubic, 1e-4) {
  const mcrt::Cubic f;
  return unbiased_p_value(f, f.domain, f.domain.length(), seed, 200, 1000);
}

// The slide's x cos x on [0, pi/2]: I = pi/2 - 1. 200 trials of N = 1000.
MCRT_STATISTICAL_CHECK(monte_carlo_unbiased_on_x_cos_x, 1e-4) {
  const mcrt::XCosX f;
  return unbiased_p_value(f, f.domain, f.domain.length(), seed, 200, 1000);
}

// The chapter's smooth k-dimensional integrand at k = 5: I = (sqrt(pi)/2 erf 1)^5.
MCRT_STATISTICAL_CHECK(monte_carlo_unbiased_on_gaussian_product_5d, 1e-4) {
  const mcrt::GaussianProduct f{5};
  return unbiased_p_value(f, f.domain(), f.domain().volume(), seed, 100, 1000);
}

// The chapter's discontinuous k-dimensional integrand at k = 3: I = V_3 = 4 pi / 3.
MCRT_STATISTICAL_CHECK(monte_carlo_unbiased_on_unit_ball_3d, 1e-4) {
  const mcrt::UnitBallIndicator f{3};
  return unbiased_p_value(f, f.domain(), f.domain().volume(), seed, 100, 1000);
}

// The spread of F_N over T = 400 trials against the closed form V[F_N]: chi-square test of
// the sample variance. It assumes normal F_N; at N = 1000 the excess kurtosis of F_N is that
// of f(X) divided by N (about -1e-3 for x cos x), which changes the variance of s^2 by a
// relative 5e-4: negligible. False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(monte_carlo_variance_matches_closed_form, 1e-4) {
  const mcrt::XCosX f;
  const int trials = 400;
  const std::uint64_t n = 1000;
  mcrt::RunningStats estimates;
  for (int t = 0; t < trials; ++t) {
    mcrt::Rng rng(seed, 1000 + static_cast<std::uint64_t>(t));
    estimates.add(mcrt::monte_carlo(f, f.domain, n, rng).estimate);
  }
  const double v_f_n =
      mcrt::monte_carlo_variance(f.domain.length(), f.reference(), f.integral_of_square(), n);
  return mcrt::testing::variance_test_p_value(estimates.variance(), trials, v_f_n);
}

// The rmse slope. At each N of a log grid (30 .. 3000, 10 per decade: 21 points), the
// mean squared error over T trials of normal F_N is V[F_N] chi^2_T / T, so
//   log rmse(N) = 1/2 log V[F_N] + 1/2 log(chi^2_T / T),
// a line of slope -1/2 in log N plus independent noise whose variance is trigamma(T/2) / 4
// (the variance of log chi^2_T is trigamma(T/2)) and whose mean is the same at every N, so
// it shifts the intercept only. The least-squares slope is then normal with mean -1/2 and
// standard deviation sqrt(trigamma(T/2) / 4 / Sxx), Sxx = sum (log N - mean)^2: with T = 100,
// 0.011, and alpha = 1e-4 accepts |slope + 1/2| < 0.044. (F_N is near normal from N = 30 on:
// the variance of the mean squared error is V^2 (2 + kappa / N) / T, kappa = the excess
// kurtosis of x cos x(X), -1.0, so at N = 30 the noise is 1 % smaller than assumed.)
MCRT_STATISTICAL_CHECK(monte_carlo_rmse_slope_is_minus_one_half, 1e-4) {
  const mcrt::XCosX f;
  const int trials = 100;
  const std::vector<std::uint64_t> grid = mcrt::log_grid(30, 3000, 10);
  std::vector<double> n_values, rmse;
  for (std::size_t g = 0; g < grid.size(); ++g) {
    double squared_error = 0.0;
    for (int t = 0; t < trials; ++t) {
      mcrt::Rng rng(seed, mcrt::stream_index(2000 + g, static_cast<std::uint64_t>(t)));
      const double error = mcrt::monte_carlo(f, f.domain, grid[g], rng).estimate - f.reference();
      squared_error += error * error / trials;
    }
    n_values.push_back(static_cast<double>(grid[g]));
    rmse.push_back(std::sqrt(squared_error));
  }
  const mcrt::LineFit fit = mcrt::fit_log_log(n_values, rmse);
  double mean_log_n = 0.0, sxx = 0.0;
  for (double n : n_values) mean_log_n += std::log(n) / static_cast<double>(n_values.size());
  for (double n : n_values) sxx += (std::log(n) - mean_log_n) * (std::log(n) - mean_log_n);
  const double slope_sd = std::sqrt(boost::math::trigamma(trials / 2.0) / 4.0 / sxx);
  return mcrt::testing::z_test_p_value(fit.slope, -0.5, slope_sd);
}

}  // namespace
