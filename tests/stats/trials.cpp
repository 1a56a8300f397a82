#include "stats/trials.hpp"

#include <array>

#include "stats/hypothesis.hpp"

namespace mcrt::testing {

RunningStats summarize(std::span<const double> values) {
  RunningStats stats;
  for (double x : values) stats.add(x);
  return stats;
}

double trials_p_value(std::span<const double> estimates, double mean, double variance) {
  const RunningStats stats = summarize(estimates);
  const std::array<double, 2> p{t_test_p_value(stats.mean(), stats.variance(), stats.count(), mean),
                                variance_test_p_value(stats.variance(), stats.count(), variance)};
  return sidak_p_value(p);
}

}  // namespace mcrt::testing
