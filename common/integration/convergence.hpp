#pragma once
/// The rate at which an error falls with the number of samples N: the slope of
/// log(error) = log(c) + slope log(N), fitted by least squares, and a guide line of a
/// predicted slope through the centre of the data for plots,
///   c N^theory  with  log c = mean(log error) - theory mean(log N).

#include <cmath>
#include <cstddef>
#include <vector>

#include "integration/statistics.hpp"

namespace mcrt {

/// A fitted convergence slope and the guide line of the predicted one.
struct ErrorSlope {
  LineFit fit;                  ///< all zero when fewer than 2 points
  std::size_t points = 0;       ///< points in the fit (zero errors have no logarithm)
  double guide_constant = 0.0;  ///< c of the guide line c N^theory
};

/// Fits log(error) against log(n) over the points with error > 0, and the constant of the
/// guide line of slope `theory` through their centre.
inline ErrorSlope fit_error_slope(const std::vector<double>& n, const std::vector<double>& error,
                                  double theory) {
  std::vector<double> kept_n, kept_error;
  for (std::size_t i = 0; i < n.size(); ++i)
    if (error[i] > 0.0) {
      kept_n.push_back(n[i]);
      kept_error.push_back(error[i]);
    }
  ErrorSlope slope;
  slope.points = kept_n.size();
  if (kept_n.size() >= 2) slope.fit = fit_log_log(kept_n, kept_error);
  const double count = static_cast<double>(kept_n.size());
  double mean_log_n = 0.0, mean_log_error = 0.0;
  for (std::size_t i = 0; i < kept_n.size(); ++i) {
    mean_log_n += std::log(kept_n[i]) / count;
    mean_log_error += std::log(kept_error[i]) / count;
  }
  slope.guide_constant = std::exp(mean_log_error - theory * mean_log_n);
  return slope;
}

}  // namespace mcrt
