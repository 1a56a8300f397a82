#include "stats/convergence.hpp"

#include <cmath>
#include <stdexcept>

#include <boost/math/distributions/students_t.hpp>

namespace mcrt::testing {

SlopeEstimate log_log_slope(std::span<const double> n, std::span<const double> error,
                            double level) {
  if (n.size() != error.size() || n.size() < 3)
    throw std::invalid_argument("log_log_slope: needs at least 3 (n, error) pairs");
  const LineFit fit = fit_log_log(n, error);
  SlopeEstimate s;
  s.slope = fit.slope;
  s.standard_error = fit.slope_standard_error;
  s.dof = static_cast<double>(n.size() - 2);
  s.level = level;
  const double half_width = student_t_quantile(0.5 + level / 2.0, s.dof) * s.standard_error;
  s.confidence = {s.slope - half_width, s.slope + half_width};
  return s;
}

double slope_p_value(const SlopeEstimate& fit, double expected_slope) {
  if (fit.standard_error <= 0.0) return fit.slope == expected_slope ? 1.0 : 0.0;
  namespace bm = boost::math;
  const double t = std::abs(fit.slope - expected_slope) / fit.standard_error;
  return 2.0 * bm::cdf(bm::complement(bm::students_t(fit.dof), t));
}

}  // namespace mcrt::testing
