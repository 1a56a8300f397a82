// Independent trials: a small Monte Carlo estimate (see small_trials.hpp) is unbiased at every
// N, not only for large N, trials drawn from Rng(seed, trial) are independent, and so are the
// generator's consecutive streams themselves.

#include <array>

#include "support/small_trials.hpp"
#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"

namespace {

// 4000 trials of F_16 for e^(-x^2) on [0, 1]: mean and variance against the closed forms.
// False-failure rate alpha = 1e-4.
MCRT_STATISTICAL_CHECK(monte_carlo_trials_unbiased_and_independent_at_n16, 1e-4) {
  return mcrt::testing::small_trials_p_value(mcrt::testing::gaussian_estimate, seed);
}

}  // namespace

namespace {

// Trials, pixels and paths take consecutive streams of one seed, Rng(seed, 0), Rng(seed, 1),
// ..., so the k-th numbers of consecutive streams must behave like independent uniforms: the
// mean of the k-th uniform over G consecutive streams has variance 1/(12 G). Over 50 groups of
// G = 40000 streams (streams 0..1999999) the group means are tested for that variance with the
// chi-square variance test (a mean of 40000 uniforms is normal), for each of the first four
// draws k, Sidak-combined. It catches streams whose numbers lie on a lattice (variance far
// below 1/(12 G)) or move together (far above): pcg32 seeded with the raw (seed, stream), as
// Rng was before it scrambled its starting state, starts consecutive streams from states in
// arithmetic progression, and gave variance ratios 0.05, 0.3, 1.0 and 0.04 for the four draws
// (p = 2e-27 at the suite seed). False-failure rate alpha = 1e-4.
MCRT_STATISTICAL_CHECK(consecutive_streams_are_independent, 1e-4) {
  constexpr int k_groups = 50, k_group_size = 40000, k_draws = 4;
  std::array<mcrt::RunningStats, k_draws> group_means;
  for (int g = 0; g < k_groups; ++g) {
    std::array<double, k_draws> sum{};
    for (int s = 0; s < k_group_size; ++s) {
      mcrt::Rng rng(seed, static_cast<std::uint64_t>(g * k_group_size + s));
      for (double& x : sum) x += rng.uniform();
    }
    for (int k = 0; k < k_draws; ++k) group_means[k].add(sum[k] / k_group_size);
  }
  std::array<double, k_draws> p{};
  for (int k = 0; k < k_draws; ++k)
    p[k] = mcrt::testing::variance_test_p_value(group_means[k].variance(), k_groups,
                                                1.0 / (12.0 * k_group_size));
  return mcrt::testing::sidak_p_value(p);
}

}  // namespace
