#include "stats/hypothesis.hpp"

#include <algorithm>
#include <cmath>

#include <vector>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace mcrt::testing {

namespace bm = boost::math;

double z_test_p_value(double estimate, double expected, double standard_error) {
  if (standard_error <= 0.0) return estimate == expected ? 1.0 : 0.0;
  const double z = std::abs(estimate - expected) / standard_error;
  return 2.0 * bm::cdf(bm::complement(bm::normal(), z));
}

double t_test_p_value(double sample_mean, double sample_variance, std::uint64_t n,
                      double expected) {
  const double standard_error = std::sqrt(sample_variance / static_cast<double>(n));
  if (standard_error <= 0.0) return sample_mean == expected ? 1.0 : 0.0;
  const double t = std::abs(sample_mean - expected) / standard_error;
  return 2.0 * bm::cdf(bm::complement(bm::students_t(static_cast<double>(n - 1)), t));
}

double variance_test_p_value(double sample_variance, std::uint64_t n, double expected_variance) {
  if (expected_variance <= 0.0) return sample_variance == 0.0 ? 1.0 : 0.0;
  // Identical values from a distribution with spread: impossible, so p = 0 (Boost's chi-square
  // CDF at 0 overflows in its gamma function for large dof instead of returning 0).
  if (sample_variance <= 0.0) return 0.0;
  const double dof = static_cast<double>(n - 1);
  const double statistic = dof * sample_variance / expected_variance;
  const bm::chi_squared chi2(dof);
  const double lower = bm::cdf(chi2, statistic);
  const double upper = bm::cdf(bm::complement(chi2, statistic));
  return std::min(1.0, 2.0 * std::min(lower, upper));
}

double variance_z_test_p_value(double sample_variance, std::uint64_t n, double expected_variance,
                               double fourth_central_moment) {
  const auto count = static_cast<double>(n);
  const double sigma4 = expected_variance * expected_variance;
  const double variance_of_s2 =
      (fourth_central_moment - sigma4 * (count - 3.0) / (count - 1.0)) / count;
  return z_test_p_value(sample_variance, expected_variance, std::sqrt(variance_of_s2));
}

double variance_z_test_p_value(std::span<const double> values, double expected_variance) {
  const auto n = static_cast<double>(values.size());
  double mean = 0.0;
  for (double x : values) mean += x;
  mean /= n;
  double m2 = 0.0, m4 = 0.0;  // central moments, divided by n
  for (double x : values) {
    const double d2 = (x - mean) * (x - mean);
    m2 += d2;
    m4 += d2 * d2;
  }
  m2 /= n;
  m4 /= n;
  const double sample_variance = m2 * n / (n - 1.0);
  if (!(m2 > 0.0) || !(expected_variance > 0.0))
    return sample_variance == expected_variance ? 1.0 : 0.0;
  const double kurtosis = m4 / (m2 * m2);
  return variance_z_test_p_value(sample_variance, values.size(), expected_variance,
                                 kurtosis * expected_variance * expected_variance);
}

double chi_square_upper_tail(double x, double dof) {
  return bm::cdf(bm::complement(bm::chi_squared(dof), x));
}

double normal_quantile(double p) { return bm::quantile(bm::normal(), p); }

double student_t_quantile(double p, double dof) { return bm::quantile(bm::students_t(dof), p); }

double sidak_alpha(double alpha, int tests) {
  return 1.0 - std::pow(1.0 - alpha, 1.0 / static_cast<double>(tests));
}

double sidak_p_value(double smallest_p, int tests) {
  // 1 - (1 - p)^m computed as -expm1(m log1p(-p)), exact also for tiny p.
  return -std::expm1(static_cast<double>(tests) * std::log1p(-std::clamp(smallest_p, 0.0, 1.0)));
}

double sidak_p_value(std::span<const double> p_values) {
  double smallest = 1.0;
  for (double p : p_values) smallest = std::min(smallest, p);
  return sidak_p_value(smallest, static_cast<int>(p_values.size()));
}

ConfidenceInterval binomial_confidence_interval(std::uint64_t successes, std::uint64_t trials,
                                                double level) {
  using bm::binomial_distribution;
  const double tail = (1.0 - level) / 2.0;
  const auto n = static_cast<double>(trials), k = static_cast<double>(successes);
  return {binomial_distribution<>::find_lower_bound_on_p(n, k, tail),
          binomial_distribution<>::find_upper_bound_on_p(n, k, tail)};
}

double binomial_test_p_value(std::uint64_t successes, std::uint64_t trials, double rate) {
  const bm::binomial_distribution<> binomial(static_cast<double>(trials), rate);
  const auto k = static_cast<double>(successes);
  const double at_most = bm::cdf(binomial, k);
  const double at_least = successes == 0 ? 1.0 : bm::cdf(bm::complement(binomial, k - 1.0));
  return std::min(1.0, 2.0 * std::min(at_most, at_least));
}

double uniformity_ks_statistic(std::span<const double> values) {
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const auto n = static_cast<double>(sorted.size());
  double d = 0.0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    const double x = std::clamp(sorted[i], 0.0, 1.0);
    // The empirical CDF jumps from i/n to (i+1)/n at x.
    d = std::max({d, static_cast<double>(i + 1) / n - x, x - static_cast<double>(i) / n});
  }
  return d;
}

double ks_p_value(double d, std::uint64_t n) {
  const double root_n = std::sqrt(static_cast<double>(n));
  const double lambda = (root_n + 0.12 + 0.11 / root_n) * d;
  if (lambda < 0.2) return 1.0;  // the series converges slowly here and Q(l) = 1 to 1e-20
  double sum = 0.0, sign = 1.0;
  for (int k = 1; k <= 100; ++k) {
    const double term = sign * std::exp(-2.0 * k * k * lambda * lambda);
    sum += term;
    if (std::abs(term) < 1e-16) break;
    sign = -sign;
  }
  return std::clamp(2.0 * sum, 0.0, 1.0);
}

}  // namespace mcrt::testing
