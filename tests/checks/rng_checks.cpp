// The generator's uniforms: U ~ Uniform[0,1) has mean 1/2 and variance 1/12.

#include "check.hpp"
#include "hypothesis.hpp"
#include "rng.hpp"
#include "statistics.hpp"

namespace {

constexpr int k_draws = 100000;

// Mean of n uniforms: E = 1/2, V = 1/(12 n). z-test, false-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(rng_uniform_mean_is_one_half, 1e-4) {
  mcrt::Rng rng(seed, 0);
  mcrt::RunningStats stats;
  for (int i = 0; i < k_draws; ++i) stats.add(rng.uniform());
  return mcrt::stats::z_test_p_value(stats.mean(), 0.5, std::sqrt(1.0 / 12.0 / k_draws));
}

// Sample variance of n uniforms against 1/12. The uniform is not normal, so the chi-square
// variance test does not apply; the sample variance's own variance is
// (mu4 - sigma^4 (n-3)/(n-1)) / n with mu4 = 1/80, and by the CLT a z-test on it is exact
// enough at n = 1e5. False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(rng_uniform_variance_is_one_twelfth, 1e-4) {
  mcrt::Rng rng(seed, 1);
  mcrt::RunningStats stats;
  for (int i = 0; i < k_draws; ++i) stats.add(rng.uniform());
  const double n = k_draws, sigma2 = 1.0 / 12.0, mu4 = 1.0 / 80.0;
  const double var_of_var = (mu4 - sigma2 * sigma2 * (n - 3.0) / (n - 1.0)) / n;
  return mcrt::stats::z_test_p_value(stats.variance(), sigma2, std::sqrt(var_of_var));
}

}  // namespace
