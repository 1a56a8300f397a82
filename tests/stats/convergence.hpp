#pragma once
// Convergence rates: the least-squares slope of log(error) against log(N), with a confidence
// interval from Student's t. For Monte Carlo the slope is -1/2; for the trapezoid rule on a
// smooth integrand, -2.

#include <cstdint>
#include <span>

#include "integration/statistics.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

/// A fitted slope with its confidence interval.
struct SlopeEstimate {
  double slope = 0.0;
  double standard_error = 0.0;    ///< from the residuals of the fit
  double dof = 0.0;               ///< points - 2
  ConfidenceInterval confidence;  ///< slope -+ t_{dof, (1+level)/2} standard_error
  double level = 0.0;
};

/// Fits log(error) = c + slope log(n) (mcrt::fit_log_log) and gives the slope's two-sided
/// confidence interval at `level`. The interval is valid when the log errors scatter about a
/// line independently with equal variance: e.g. each error an rms over the same number of
/// independent trials. Needs at least 3 points.
SlopeEstimate log_log_slope(std::span<const double> n, std::span<const double> error,
                            double level = 0.99);

/// Two-sided t-test of a fitted slope against `expected_slope`:
/// t = (slope - expected) / standard_error with points - 2 degrees of freedom.
double slope_p_value(const SlopeEstimate& fit, double expected_slope);

}  // namespace mcrt::testing
