#pragma once
/// Running mean and variance, standard error, and the least-squares slope of log(error)
/// against log(N): the numbers every convergence study reports.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace mcrt {

/// Welford's running mean and variance: numerically stable in one pass.
class RunningStats {
 public:
  void add(double x) {
    ++count_;
    const double delta = x - mean_;
    mean_ += delta / static_cast<double>(count_);
    m2_ += delta * (x - mean_);
  }

  /// Merges another accumulator (Chan et al.), so per-thread stats can be combined in order.
  void merge(const RunningStats& other) {
    if (other.count_ == 0) return;
    const double n = static_cast<double>(count_ + other.count_);
    const double delta = other.mean_ - mean_;
    mean_ += delta * static_cast<double>(other.count_) / n;
    m2_ += other.m2_ +
           delta * delta * static_cast<double>(count_) * static_cast<double>(other.count_) / n;
    count_ += other.count_;
  }

  std::uint64_t count() const { return count_; }
  double mean() const { return mean_; }
  /// Unbiased sample variance s^2 = sum (x - mean)^2 / (n - 1); 0 for fewer than 2 values.
  double variance() const { return count_ > 1 ? m2_ / static_cast<double>(count_ - 1) : 0.0; }
  double stddev() const { return std::sqrt(variance()); }
  /// Standard error of the mean, s / sqrt(n).
  double standard_error() const {
    return count_ > 0 ? std::sqrt(variance() / static_cast<double>(count_)) : 0.0;
  }

 private:
  std::uint64_t count_ = 0;
  double mean_ = 0.0;
  double m2_ = 0.0;
};

/// Repeated independent estimates of a known value: their mean, bias, spread and
/// root-mean-square error rmse = sqrt(mean (estimate - exact)^2) = sqrt(bias^2 + (T-1)/T s^2).
class ErrorStats {
 public:
  explicit ErrorStats(double exact) : exact_(exact) {}

  void add(double estimate) {
    stats_.add(estimate);
    squared_error_ += (estimate - exact_) * (estimate - exact_);
  }

  std::uint64_t count() const { return stats_.count(); }
  double mean() const { return stats_.mean(); }
  double bias() const { return stats_.mean() - exact_; }
  /// Sample standard deviation s of the estimates (n - 1 in the denominator).
  double stddev() const { return stats_.stddev(); }
  double rmse() const {
    return count() > 0 ? std::sqrt(squared_error_ / static_cast<double>(count())) : 0.0;
  }

 private:
  double exact_;
  RunningStats stats_;
  double squared_error_ = 0.0;
};

/// The middle value (the mean of the two middle values for an even count); needs a value.
inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

/// Least-squares line y = intercept + slope x, with the slope's standard error.
struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
  double slope_standard_error = 0.0;  ///< sqrt(residual variance / sum (x - mean x)^2)
};

/// Ordinary least squares; needs at least 2 points (3 for a standard error).
inline LineFit fit_line(std::span<const double> x, std::span<const double> y) {
  const std::size_t n = x.size();
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_x += x[i];
    mean_y += y[i];
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mean_x) * (x[i] - mean_x);
    sxy += (x[i] - mean_x) * (y[i] - mean_y);
  }
  LineFit fit;
  fit.slope = sxy / sxx;
  fit.intercept = mean_y - fit.slope * mean_x;
  if (n > 2) {
    double residuals = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = y[i] - (fit.intercept + fit.slope * x[i]);
      residuals += r * r;
    }
    fit.slope_standard_error = std::sqrt(residuals / static_cast<double>(n - 2) / sxx);
  }
  return fit;
}

/// Slope of log(error) against log(n): the convergence rate (-1/2 for Monte Carlo).
inline LineFit fit_log_log(std::span<const double> n, std::span<const double> error) {
  std::vector<double> log_n, log_error;
  for (std::size_t i = 0; i < n.size(); ++i) {
    log_n.push_back(std::log(n[i]));
    log_error.push_back(std::log(error[i]));
  }
  return fit_line(log_n, log_error);
}

}  // namespace mcrt
