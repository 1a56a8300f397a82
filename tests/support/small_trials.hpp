#pragma once
// Independent trials of a small Monte Carlo estimate, against the closed forms of its mean and
// variance. Written for any estimator and any trial runner, so the check
// (tests/stats/trials_checks.cpp) runs it on the project's and the known-bug tests on the wrong
// ones of tests/integration/monte_carlo_known_bugs.hpp (which it must reject).
//
// F_N = 1/N sum e^(-X_i^2), X_i uniform on [0, 1] (Gaussian1D of common/integration/integrands.hpp):
//   E[F_N] = I = sqrt(pi)/2 erf(1),   V[F_N] = (J - I^2) / N,   J = sqrt(pi/8) erf(sqrt 2).
// At N = 16 a bias like I / (N - 1) is 60 standard errors of the mean of 4000 trials, while at
// the N of the convergence studies it would hide in the noise; trials that share a generator
// stream are identical and have sample variance 0.

#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "integration/integrands.hpp"
#include "integration/monte_carlo.hpp"
#include "stats/trials.hpp"

namespace mcrt::testing {

inline constexpr std::uint64_t k_small_trial_samples = 16;  // N per trial
inline constexpr std::uint64_t k_small_trials = 4000;       // T

/// The project's estimator: F_N of mcrt::monte_carlo.
inline double gaussian_estimate(std::uint64_t n, Rng& rng) {
  const Gaussian1D f;
  return monte_carlo(f, f.domain, n, rng).estimate;
}

/// The project's way of running trials: trial t draws from Rng(seed, t).
struct IndependentTrials {
  template <class Estimator>
  std::vector<double> operator()(const Estimator& estimate, std::uint64_t trials,
                                 std::uint64_t seed) const {
    return run_trials(estimate, trials, seed);
  }
};

/// T trials of F_N made by `run(estimate, T, seed)` with `estimate(N, rng)`, tested by
/// trials_p_value: Sidak over a t-test of their mean against I and a chi-square test of
/// their variance against V[F_N]. The chi-square test assumes normal trials: e^(-x^2) is
/// bounded, so F_16 has excess kurtosis (that of f, about -1.1) / 16 = -0.07 and the test's
/// true false-failure rate is a little below its nominal one.
template <class Estimator, class TrialRunner = IndependentTrials>
double small_trials_p_value(const Estimator& estimate, std::uint64_t seed,
                            const TrialRunner& run = {}) {
  const Gaussian1D f;
  const auto one_trial = [&](Rng& rng) { return estimate(k_small_trial_samples, rng); };
  const std::vector<double> trials = run(one_trial, k_small_trials, seed);
  const double variance = monte_carlo_variance(f.domain.length(), f.reference(),
                                               f.integral_of_square(), k_small_trial_samples);
  return trials_p_value(trials, f.reference(), variance);
}

}  // namespace mcrt::testing
