#pragma once
// What a fairness measurement reads from one check's single-seed p-values: on the correct
// solution, how often it rejects (false failures) and whether its p-values look uniform; on a
// known bug, how often it rejects (detection). Each rate comes with its exact (Clopper-Pearson)
// 95% bound, since the rates that matter (below 5e-4, or the misses of a bug) are too rare to
// see in a few hundred seeds.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "assignments/grading.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

/// The confidence of every bound below: two-sided 95% (one side each, 97.5%).
inline constexpr double k_bound_level = 0.95;

/// The p-values of a check on the correct solution, one per seed.
struct FalseFailures {
  std::uint64_t seeds = 0;
  std::uint64_t below_5_percent = 0, below_1_percent = 0, below_alpha = 0;
  double min_p = 1.0;
  double ks_statistic = 0.0, ks_p = 1.0;  ///< Kolmogorov-Smirnov against Uniform(0, 1)
  double rate_alpha_upper = 0.0;          ///< upper 95% bound on P(p < alpha) at one seed
  // majority_false_failure_rate (3 q^2 (1 - q) + q^3, grading.hpp) at the measured rate and
  // at its upper bound: the chance that two of three seeds reject
  double majority_rate = 0.0;
  double majority_rate_upper = 0.0;
};

inline FalseFailures false_failures(const std::vector<double>& p_values, double alpha) {
  FalseFailures f;
  f.seeds = p_values.size();
  for (double p : p_values) {
    f.below_5_percent += !(p >= 0.05);  // NaN counts as a rejection, as in SeedVerdict
    f.below_1_percent += !(p >= 0.01);
    f.below_alpha += !(p >= alpha);
    f.min_p = std::min(f.min_p, p);
  }
  f.ks_statistic = uniformity_ks_statistic(p_values);
  f.ks_p = ks_p_value(f.ks_statistic, f.seeds);
  const double n = static_cast<double>(f.seeds);
  f.rate_alpha_upper = binomial_confidence_interval(f.below_alpha, f.seeds, k_bound_level).high;
  f.majority_rate = majority_false_failure_rate(static_cast<double>(f.below_alpha) / n);
  f.majority_rate_upper = majority_false_failure_rate(f.rate_alpha_upper);
  return f;
}

/// The p-values of a check on a known bug, one per seed.
struct Detection {
  std::uint64_t seeds = 0, rejected = 0;
  double max_p = 0.0;
  double rate_lower = 0.0;           ///< lower 95% bound on P(p < alpha) at one seed
  double majority_rate_lower = 0.0;  ///< 3 q^2 (1 - q) + q^3 at q = rate_lower: two of three reject
};

inline Detection detection(const std::vector<double>& p_values, double alpha) {
  Detection d;
  d.seeds = p_values.size();
  for (double p : p_values) {
    d.rejected += !(p >= alpha);
    d.max_p = std::max(d.max_p, p);
  }
  d.rate_lower = binomial_confidence_interval(d.rejected, d.seeds, k_bound_level).low;
  d.majority_rate_lower = majority_false_failure_rate(d.rate_lower);
  return d;
}

}  // namespace mcrt::testing::assignment
