#pragma once
/// Plain Monte Carlo integration with uniform samples over a Segment or a Box.
///
///   F_N = vol / N * sum_{i=1..N} f(X_i),   X_i independent and uniform in the domain,
///   E[F_N] = vol E[f(X)] = I                      (unbiased for every N),
///   V[F_N] = vol^2 Var f(X) / N = (vol J - I^2) / N,   J = integral of f^2,
/// so its rms error falls as N^(-1/2) in every dimension.
///
/// The integrand is any callable, inlined into the loop: f(double) on a Segment,
/// f(std::span<const double>) on a Box. Random numbers come from the caller's stream, so the
/// caller decides which stream (trial, pixel) a run uses. Nothing is allocated.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/rng.hpp"
#include "integration/domain.hpp"

namespace mcrt {

/// An estimate F_N and its standard error vol * s / sqrt(N), s^2 the sample variance of f(X).
struct MonteCarloEstimate {
  double estimate = 0.0;
  double standard_error = 0.0;
};

namespace detail {

// F_N and its standard error from sum f(X_i) and sum f(X_i)^2 (values of f here are O(1), so
// the one-pass variance loses nothing that matters next to its own statistical error).
inline MonteCarloEstimate finish_estimate(double volume, double sum, double sum_of_squares,
                                          std::uint64_t n) {
  const auto count = static_cast<double>(n);
  const double mean = sum / count;
  const double variance =
      n > 1 ? std::fmax(0.0, (sum_of_squares - sum * mean) / (count - 1.0)) : 0.0;
  return {volume * mean, volume * std::sqrt(variance / count)};
}

}  // namespace detail

/// F_N over `segment` with n >= 1 samples drawn from `rng`.
template <class F>
MonteCarloEstimate monte_carlo(F&& f, const Segment& segment, std::uint64_t n, Rng& rng) {
  // ASSIGNMENT a1.3 BEGIN stub: (void)f; (void)segment; (void)n; (void)rng; NOT_IMPLEMENTED(monte_carlo on a Segment);
  const double length = segment.length();
  double sum = 0.0, sum_of_squares = 0.0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double f_x = f(segment.lower + rng.uniform() * length);
    sum += f_x;
    sum_of_squares += f_x * f_x;
  }
  return detail::finish_estimate(length, sum, sum_of_squares, n);
  // ASSIGNMENT a1.3 END
}

/// F_N over `box` with n >= 1 samples drawn from `rng` (dims uniforms per sample, axis 0
/// first). Samples are drawn a batch at a time, then evaluated (see PointBatch).
template <class F>
MonteCarloEstimate monte_carlo(F&& f, const Box& box, std::uint64_t n, Rng& rng) {
  // ASSIGNMENT a1.3 BEGIN withheld stub: (void)f; (void)box; (void)n; (void)rng; NOT_IMPLEMENTED(monte_carlo on a Box);
  PointBatch batch;
  batch.dims = box.dims;
  double sum = 0.0, sum_of_squares = 0.0;
  for (std::uint64_t first = 0; first < n; first += k_point_batch) {
    const auto count = static_cast<std::size_t>(std::min<std::uint64_t>(k_point_batch, n - first));
    for (std::size_t j = 0; j < count; ++j) {
      double* x = batch.point(j);
      for (int axis = 0; axis < box.dims; ++axis)
        x[axis] = box.lower[axis] + rng.uniform() * (box.upper[axis] - box.lower[axis]);
    }
    for (std::size_t j = 0; j < count; ++j) {
      const double f_x = f(batch[j]);
      sum += f_x;
      sum_of_squares += f_x * f_x;
    }
  }
  return detail::finish_estimate(box.volume(), sum, sum_of_squares, n);
  // ASSIGNMENT a1.3 END
}

/// V[F_N] = (vol J - I^2) / N from the closed forms I = integral of f, J = integral of f^2.
inline double monte_carlo_variance(double volume, double integral, double integral_of_square,
                                   std::uint64_t n) {
  return (volume * integral_of_square - integral * integral) / static_cast<double>(n);
}

}  // namespace mcrt
