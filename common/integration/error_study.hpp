#pragma once
/// Repeated independent estimates at one sample size, the raw material of every study of error
/// against N: T estimates F_1..F_T of a known I give
///   mean = (1/T) sum F_t,   bias = mean - I,   s^2 = sum (F_t - mean)^2 / (T - 1),
///   rmse = sqrt((1/T) sum (F_t - I)^2) = sqrt(bias^2 + (T - 1)/T s^2).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "integration/statistics.hpp"

namespace mcrt {

/// `trials` estimates F_t = estimate(n, rng) of `exact`, rng = Rng(seed, stream_of(t)), run in
/// parallel over t and accumulated in the order of t: the result does not depend on
/// `threads`. Advances `progress` by n per estimate.
template <class Estimate, class StreamOf>
ErrorStats repeated_estimates(std::uint64_t n, int trials, double exact, std::uint64_t seed,
                              int threads, ProgressBar& progress, Estimate&& estimate,
                              StreamOf&& stream_of) {
  std::vector<double> estimates(static_cast<std::size_t>(trials));
  parallel_for(estimates.size(), threads, [&](std::size_t t) {
    Rng rng(seed, stream_of(static_cast<std::uint64_t>(t)));
    estimates[t] = estimate(n, rng);
    progress.advance(n);
  });
  ErrorStats errors(exact);
  for (double f : estimates) errors.add(f);
  return errors;
}

}  // namespace mcrt
