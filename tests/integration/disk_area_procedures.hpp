#pragma once
// The statistical procedures behind the disk-area checks, written once for any estimator
// double(n, Rng&) so the checks run them on the project's estimators and the unit tests run
// them on known-wrong variants (which they must reject). Each returns a p-value.

#include <cmath>
#include <cstdint>
#include <vector>

#include <boost/math/distributions/students_t.hpp>

#include "core/rng.hpp"
#include "integration/log_grid.hpp"
#include "integration/statistics.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

/// Sample sizes for the pooled mean test: tiny ones (where 4 M / N takes a handful of values),
/// sizes that are not multiples of the 16 generator lanes, and a few large ones.
inline const std::vector<std::uint64_t> k_pooled_sizes = {1,    2,    10,    17,      100,
                                                          1000, 4099, 65536, 1000003, 4194319};

/// Pooled z-test of the mean. `trials` estimates F_i at every size n_i, from streams
/// (stream_base + i, trial). The weighted mean sum n_i F_i / sum n_i is again unbiased, with
/// variance sum n_i^2 V[F_i] / (sum n_i)^2, V[F_i] = theory_std(n_i)^2; over millions of
/// points it is normal to far better than the tail probability tested.
template <class Estimate, class TheoryStd>
double pooled_mean_p_value(Estimate&& estimate, double exact, TheoryStd&& theory_std, int trials,
                           std::uint64_t seed, std::uint64_t stream_base) {
  double weighted_sum = 0.0, total_n = 0.0, weighted_variance = 0.0;
  for (std::size_t i = 0; i < k_pooled_sizes.size(); ++i) {
    const std::uint64_t n = k_pooled_sizes[i];
    const double n_d = static_cast<double>(n), sigma = theory_std(n);
    for (int t = 0; t < trials; ++t) {
      Rng rng(seed, stream_index(stream_base + i, static_cast<std::uint64_t>(t)));
      weighted_sum += n_d * estimate(n, rng);
      total_n += n_d;
      weighted_variance += n_d * n_d * sigma * sigma;
    }
  }
  return z_test_p_value(weighted_sum / total_n, exact, std::sqrt(weighted_variance) / total_n);
}

/// The sample variance s^2 of `trials` estimates |box| M / N at one n, against its closed form
/// sigma^2 = |box|^2 p (1 - p) / N. Binomial estimates are not normal, so instead of the
/// chi-square test this uses the exact variance of s^2, (mu4 - sigma^4 (T - 3) / (T - 1)) / T,
/// with the binomial's fourth central moment mu4 = |box|^4 N p q (1 + 3 (N - 2) p q) / N^4,
/// and a z-test: s^2 is a mean of T terms, normal by the CLT at T in the thousands.
template <class Estimate>
double variance_p_value(Estimate&& estimate, double box_volume, double p, std::uint64_t n,
                        int trials, std::uint64_t seed, std::uint64_t stream) {
  RunningStats stats;
  for (int t = 0; t < trials; ++t) {
    Rng rng(seed, stream_index(stream, static_cast<std::uint64_t>(t)));
    stats.add(estimate(n, rng));
  }
  const double n_d = static_cast<double>(n), q = 1.0 - p;
  const double sigma2 = box_volume * box_volume * p * q / n_d;
  const double mu4 =
      std::pow(box_volume / n_d, 4.0) * n_d * p * q * (1.0 + 3.0 * (n_d - 2.0) * p * q);
  return variance_z_test_p_value(stats.variance(), static_cast<std::uint64_t>(trials), sigma2, mu4);
}

/// The least-squares slope of log(rmse) against log(N), rmse over `trials` estimates at each
/// N of log_grid(first, last, 4), against the theory -1/2.
///
/// Design: log(rmse_i) = log(sigma) - log(N_i)/2 + e_i, where e_i = log of the root of a mean of
/// T squared errors over sigma^2: independent across N (separate streams), with the same
/// distribution at every N (the binomial's excess kurtosis (1 - 6 p q) / (N p q) is below 0.07
/// at p = pi/4 for every N, so var(e_i) ~ 1/(2T) does not depend on N) and close to normal for
/// T in the hundreds. So the ordinary least-squares slope is unbiased and
/// (slope + 1/2) / se(slope) follows Student's t with K - 2 degrees of freedom, se from the
/// residuals. The tolerance is therefore t_{1 - alpha/2, K-2} se(slope), about 0.03 at T = 200
/// over four decades.
struct SlopeResult {
  double slope = 0.0;
  double standard_error = 0.0;
  double p_value = 0.0;
};

template <class Estimate>
SlopeResult error_slope(Estimate&& estimate, double exact, std::uint64_t first, std::uint64_t last,
                        int trials, std::uint64_t seed, std::uint64_t stream_base) {
  std::vector<double> ns, rmses;
  const std::vector<std::uint64_t> grid = log_grid(first, last, 4);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    double squared_error = 0.0;
    for (int t = 0; t < trials; ++t) {
      Rng rng(seed, stream_index(stream_base + i, static_cast<std::uint64_t>(t)));
      const double error = estimate(grid[i], rng) - exact;
      squared_error += error * error;
    }
    ns.push_back(static_cast<double>(grid[i]));
    rmses.push_back(std::sqrt(squared_error / trials));
  }
  const LineFit fit = fit_log_log(ns, rmses);
  const double dof = static_cast<double>(grid.size()) - 2.0;
  const double t = std::abs(fit.slope + 0.5) / fit.slope_standard_error;
  const double p = 2.0 * boost::math::cdf(boost::math::complement(boost::math::students_t(dof), t));
  return {fit.slope, fit.slope_standard_error, p};
}

}  // namespace mcrt::testing
