#pragma once
// Independent trials of an estimator, and the test of their mean and variance against closed
// forms. The trial runner is a parameter of the tests, so that a wrong one (a generator
// stream reused across trials) can be plugged in and shown to be caught.

#include <cstdint>
#include <span>
#include <vector>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

/// Runs `trials` independent trials estimate(rng) in parallel; trial t draws from
/// Rng(seed, t), so the results do not depend on the threads.
template <class Estimator>
std::vector<double> run_trials(const Estimator& estimate, std::uint64_t trials, std::uint64_t seed,
                               int threads = 1) {
  std::vector<double> estimates(trials);
  parallel_for(trials, threads, [&](std::size_t t) {
    Rng rng(seed, t);
    estimates[t] = estimate(rng);
  });
  return estimates;
}

/// Tests T independent trial estimates against the closed-form mean and variance of one
/// trial: the Sidak-combined p-value of
///  - the t-test of their mean against `mean` (T - 1 degrees of freedom), and
///  - the chi-square test of their sample variance against `variance`,
///    (T - 1) s^2 / sigma^2 ~ chi^2(T - 1), which assumes normal estimates: use trials that
///    average enough samples for the central limit theorem to hold (see the callers).
/// Trials that are not independent (a stream reused) have too small a variance; a biased
/// estimator has the wrong mean.
double trials_p_value(std::span<const double> estimates, double mean, double variance);

/// The t-test p-value of the mean of `count` draws draw(rng), draw i from Rng(seed, i),
/// against `expected` (for estimators whose single draws are far from normal, such as one
/// path of a path tracer: only the mean is tested, which the central limit theorem covers).
template <class Draw>
double mean_p_value(const Draw& draw, std::uint64_t count, std::uint64_t seed, double expected) {
  RunningStats stats;
  for (std::uint64_t i = 0; i < count; ++i) {
    Rng rng(seed, i);
    stats.add(draw(rng));
  }
  return t_test_p_value(stats.mean(), stats.variance(), stats.count(), expected);
}

/// The mean and variance of values, as RunningStats.
RunningStats summarize(std::span<const double> values);

}  // namespace mcrt::testing
