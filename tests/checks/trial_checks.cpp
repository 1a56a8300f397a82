// Independent trials of a small Monte Carlo estimate (see small_trials.hpp): the estimator is
// unbiased at every N, not only for large N, and trials drawn from Rng(seed, trial) are
// independent.

#include "check.hpp"
#include "small_trials.hpp"

namespace {

// 4000 trials of F_16 for e^(-x^2) on [0, 1]: mean and variance against the closed forms.
// False-failure rate alpha = 1e-4.
MCRT_STATISTICAL_CHECK(monte_carlo_trials_unbiased_and_independent_at_n16, 1e-4) {
  return mcrt::checks::small_trials_p_value(mcrt::checks::gaussian_estimate, seed);
}

}  // namespace
