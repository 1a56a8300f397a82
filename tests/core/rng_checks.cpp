// The generator's uniforms: U ~ Uniform[0,1) has mean 1/2 and variance 1/12.

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"

namespace {

constexpr int k_draws = 100000;

// Mean of n uniforms: E = 1/2, V = 1/(12 n). z-test, false-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(rng_uniform_mean_is_one_half, 1e-4) {
  mcrt::Rng rng(seed, 0);
  mcrt::RunningStats stats;
  for (int i = 0; i < k_draws; ++i) stats.add(rng.uniform());
  return mcrt::testing::z_test_p_value(stats.mean(), 0.5, std::sqrt(1.0 / 12.0 / k_draws));
}

// Sample variance of n uniforms against 1/12. The uniform is not normal, so the chi-square
// variance test does not apply; the suite's variance z-test takes the uniform's fourth central
// moment mu4 = 1/80, and by the CLT it is exact enough at n = 1e5. False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(rng_uniform_variance_is_one_twelfth, 1e-4) {
  mcrt::Rng rng(seed, 1);
  mcrt::RunningStats stats;
  for (int i = 0; i < k_draws; ++i) stats.add(rng.uniform());
  return mcrt::testing::variance_z_test_p_value(stats.variance(), stats.count(), 1.0 / 12.0,
                                                1.0 / 80.0);
}

}  // namespace

namespace {

// Neighbouring generators must be independent: every renderer gives pixel p, sample s the
// stream (p, s), and a student compares runs with seeds 1, 2, 3. For S streams, the
// correlation of the j-th draws of Rng(seed, s) and Rng(seed + 1, s), and of Rng(seed, s) and
// Rng(seed, s + 1), is r with sqrt(S) r ~ N(0,1) under independence (here
// r = 12 mean((u - 1/2)(v - 1/2)), since Var u = 1/12). The 2J statistics are independent, so
// their sum of squares is chi^2(2J); correlation inflates it. False-failure rate 1e-4.
MCRT_STATISTICAL_CHECK(rng_neighbouring_seeds_and_streams_are_independent, 1e-4) {
  constexpr int k_streams = 40000, k_draws_per_stream = 8;
  double seed_products[k_draws_per_stream] = {}, stream_products[k_draws_per_stream] = {};
  const std::uint64_t first = (seed % 1000) << 20;  // streams first .. first + S - 1
  for (int s = 0; s < k_streams; ++s) {
    mcrt::Rng a(seed, first + s), next_seed(seed + 1, first + s), next_stream(seed, first + s + 1);
    for (int j = 0; j < k_draws_per_stream; ++j) {
      const double u = a.uniform() - 0.5;
      seed_products[j] += u * (next_seed.uniform() - 0.5);
      stream_products[j] += u * (next_stream.uniform() - 0.5);
    }
  }
  double chi2 = 0.0;
  for (int j = 0; j < k_draws_per_stream; ++j)
    for (const double product : {seed_products[j], stream_products[j]}) {
      const double z = 12.0 * product / k_streams * std::sqrt(double(k_streams));
      chi2 += z * z;
    }
  return mcrt::testing::chi_square_upper_tail(chi2, 2 * k_draws_per_stream);
}

}  // namespace
