#pragma once
// The grading procedures of assignment a3 (the recursive estimator). They judge the bulk
// answers of `p`, a Subject or an A3Producer (a3_produce.hpp): single calls with their ray
// counts (recursive_single) and furnace samples (recursive_furnace) of incident_radiance.

#include <cmath>
#include <string>
#include <vector>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/a3/a3_produce.hpp"
#include "assignments/grading.hpp"
#include "integration/statistics.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

/// Exact: one call from the furnace's centre traces 1 + N + ... + N^k rays (none escapes).
template <class P>
TaskResult check_ray_counts(P&& producer) {
  TaskResult result{true, ""};
  for (const auto& [n, k] : std::vector<std::pair<int, int>>{{1, 0}, {1, 4}, {2, 3}, {3, 2}, {4, 1}}) {
    const std::uint64_t rays =
        producer.recursive_single(0.5, 1.0, Vec3(0.0), Vec3(0.0, 0.0, 1.0), n, k, 7, static_cast<std::uint64_t>(10 * n + k)).rays;
    const std::uint64_t expected = geometric_ray_count(static_cast<std::uint64_t>(n), k);
    const bool ok = rays == expected;
    result.passed = result.passed && ok;
    result.message += fmt::format("N = {}, k = {}: {} rays, expected {}\n", n, k, rays, expected);
    if (!ok) result.message += diagnose_ray_count(rays, static_cast<std::uint64_t>(n), k) + "\n";
  }
  return result;
}

/// The furnace of check_recursive_furnace (a = 0.5, Le = 1, N = 2, k = 3) at one seed: the
/// mean of 4000 samples t-tested against m_k = 1.875 and their variance z-tested against V_k
/// (furnace_moments), the two p-values Sidak-combined (the samples' statistics in `stats`).
template <class P>
double recursive_furnace_p_value(P&& producer, std::uint64_t seed, RunningStats& stats) {
  constexpr double a = 0.5;
  constexpr int n_branches = 2, k = 3, samples = 4000;
  const FurnaceMoments m = furnace_moments(a, n_branches, k);
  const std::vector<double> values = producer.recursive_furnace(a, n_branches, k, samples, seed, 31);
  stats = RunningStats{};
  for (double L : values) stats.add(L);
  const double p_mean = t_test_p_value(stats.mean(), stats.variance(), stats.count(), m.mean);
  const double p_variance = variance_z_test_p_value(values, m.variance);
  return sidak_p_value(std::min(p_mean, p_variance), 2);
}

/// The furnace: recursive_furnace_p_value at the three grading seeds.
template <class P>
TaskResult check_recursive_furnace(P&& producer) {
  constexpr double a = 0.5;
  constexpr int n_branches = 2, k = 3;
  const FurnaceMoments m = furnace_moments(a, n_branches, k);
  double mean_sum = 0.0, variance_sum = 0.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    RunningStats stats;
    const double p = recursive_furnace_p_value(producer, seed, stats);
    mean_sum += stats.mean();
    variance_sum += stats.variance();
    return p;
  });
  const double mean = mean_sum / k_seeds, variance = variance_sum / k_seeds;
  std::string d;
  if (!v.passed()) {
    d = diagnose_mean_ratio(mean, m.mean);
    if (near(mean, furnace_moments(a, n_branches, k - 1).mean, 0.01))
      d = diagnosis("your mean is that of depth k - 1: does your recursion stop one bounce early?");
    else if (near(mean, furnace_moments(a, n_branches, k + 1).mean, 0.01))
      d = diagnosis("your mean is that of depth k + 1: does your recursion stop one bounce late?");
    else if (near(mean, furnace_moments(a * n_branches, 1, k).mean, 0.02))
      d = diagnosis("each level weighs N a instead of a: is the sum over the N branches divided by N?");
    else if (near(mean, m.mean, 0.01) && variance > 1.2 * m.variance)
      d = diagnosis(fmt::format("the mean is right but the variance is {:.2f}x the closed form: do the N branches share one direction (each needs its own)?", variance / m.variance));
    else if (near(mean, m.mean, 0.01))
      d = diagnosis(fmt::format("the mean is right but the variance is {:.2f}x the closed form", variance / m.variance));
  }
  return {v.passed(), fmt::format("furnace N = 2, k = 3, a = 0.5: mean {:.5f} (expected {:.5f}), variance {:.5f} (expected {:.5f}); {}\n{}",
                                  mean, m.mean, variance, m.variance, v.describe(), d)};
}

}  // namespace mcrt::testing::assignment
