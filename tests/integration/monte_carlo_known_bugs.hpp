#pragma once
// Known-wrong Monte Carlo and quadrature estimators, and a wrong trial runner, kept so the
// tests can show the statistical tests reject them (tests/stats/known_bugs_test.cpp,
// tests/integration/monte_carlo_test.cpp).

#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "integration/domain.hpp"
#include "integration/integrands.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/quadrature.hpp"
#include "render/image.hpp"
#include "support/small_trials.hpp"

namespace mcrt::testing {

/// Wrong: the sum divided by N - 1 instead of N: E = I N / (N - 1), a bias of I / 15 at N = 16.
inline double estimate_dividing_by_n_minus_one(std::uint64_t n, Rng& rng) {
  const double f_n = gaussian_estimate(n, rng);  // sum / N
  return f_n * static_cast<double>(n) / static_cast<double>(n - 1);
}

/// Wrong: the two-render error without the 1/2: (A - B)^2 has twice the variance of one render,
/// so this reports 2 Var[A] per pixel and channel.
inline double two_render_error_without_the_half(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const Color d = a.pixels[i] - b.pixels[i];
    sum += glm::dot(d, d);  // should be glm::dot(d, d) / 2
  }
  return sum / (3.0 * static_cast<double>(a.pixels.size()));
}

/// Wrong: every trial starts the same stream Rng(seed, 0), so all trials are the same numbers.
struct SameStreamTrials {
  template <class Estimator>
  std::vector<double> operator()(const Estimator& estimate, std::uint64_t trials,
                                 std::uint64_t seed) const {
    std::vector<double> estimates(trials);
    for (std::uint64_t t = 0; t < trials; ++t) {
      Rng rng(seed, 0);  // should be Rng(seed, t)
      estimates[t] = estimate(rng);
    }
    return estimates;
  }
};

/// Wrong: the volume factor forgotten, 1/N sum f(X_i), which estimates I / vol.
template <class F>
double monte_carlo_without_volume(const F& f, const Segment& domain, std::uint64_t n, Rng& rng) {
  return monte_carlo(f, domain, n, rng).estimate / domain.length();
}

/// Wrong: samples from a slightly short interval [a, b - 1%], weighted by the full length.
template <class F>
double monte_carlo_on_short_interval(const F& f, const Segment& domain, std::uint64_t n, Rng& rng) {
  const Segment short_domain{domain.lower, domain.upper - 0.01 * domain.length()};
  return monte_carlo(f, short_domain, n, rng).estimate / short_domain.length() * domain.length();
}

/// Wrong, not Monte Carlo: the midpoint rule h sum f(a + (i + 1/2) h), h = (b - a) / N, passed
/// off as F_N, with a "standard error" from the spread of its f values as F_N's would be: no
/// random number drawn, zero spread (its error, (b - a) h^2 f'' / 24, is far below F_N's sd).
template <class F>
MonteCarloEstimate monte_carlo_midpoint_rule(const F& f, const Segment& domain, std::uint64_t n,
                                             Rng&) {
  const double h = domain.length() / static_cast<double>(n);
  double total = 0.0, total_of_squares = 0.0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double y = f(domain.lower + (static_cast<double>(i) + 0.5) * h);
    total += y;
    total_of_squares += y * y;
  }
  return mcrt::detail::finish_estimate(domain.length(), total, total_of_squares, n);
}

/// Wrong: full weights at the ends, h sum_{i=0..n-1} f(x_i): off by h (f(a) + f(b)) / 2, O(h).
inline double trapezoid_with_full_end_weights(const Gaussian1D& f, std::uint64_t n) {
  const double h = f.domain.length() / static_cast<double>(n - 1);
  double sum = 0.0;
  for (std::uint64_t i = 0; i < n; ++i) sum += f(grid_point(f.domain.lower, f.domain.upper, i, n));
  return h * sum;
}

}  // namespace mcrt::testing
