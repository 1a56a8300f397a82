#include "hypothesis.hpp"

#include <algorithm>
#include <cmath>

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

namespace mcrt::stats {

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
  const double dof = static_cast<double>(n - 1);
  const double statistic = dof * sample_variance / expected_variance;
  const bm::chi_squared chi2(dof);
  const double lower = bm::cdf(chi2, statistic);
  const double upper = bm::cdf(bm::complement(chi2, statistic));
  return std::min(1.0, 2.0 * std::min(lower, upper));
}

double chi_square_upper_tail(double x, double dof) {
  return bm::cdf(bm::complement(bm::chi_squared(dof), x));
}

double normal_quantile(double p) { return bm::quantile(bm::normal(), p); }

double student_t_quantile(double p, double dof) { return bm::quantile(bm::students_t(dof), p); }

double sidak_alpha(double alpha, int tests) {
  return 1.0 - std::pow(1.0 - alpha, 1.0 / static_cast<double>(tests));
}

}  // namespace mcrt::stats
