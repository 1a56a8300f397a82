#pragma once
// The grading procedures of assignment a3 (the recursive estimator). They judge the bulk
// answers of `p`, a Subject or an A3Producer (a3_produce.hpp): single calls with their ray
// counts (recursive_single) and furnace samples (recursive_furnace) of incident_radiance.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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

/// b^e, or the largest std::uint64_t when b^e exceeds it.
inline std::uint64_t saturating_power(std::uint64_t b, int e) {
  constexpr std::uint64_t k_max = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t r = 1;
  for (int i = 0; i < e; ++i) {
    if (b != 0 && r > k_max / b) return k_max;
    r *= b;
  }
  return r;
}

/// a3.2's reference, written apart from the solution: 1 + N + ... + N^k term by term,
/// saturated at the largest std::uint64_t (a power that saturates is already past it).
inline std::uint64_t reference_max_rays(std::uint64_t n, int k) {
  constexpr std::uint64_t k_max = std::numeric_limits<std::uint64_t>::max();
  std::uint64_t total = 0;
  for (int j = 0; j <= k; ++j) {
    const std::uint64_t level = saturating_power(n, j);
    if (level == k_max || total > k_max - level) return k_max;
    total += level;
  }
  return total;
}

/// Names the classic mistakes of a ray-count prediction (N branches, depth k).
inline std::string diagnose_prediction(std::uint64_t observed, std::uint64_t n, int k) {
  const auto power = saturating_power;
  const std::uint64_t expected = reference_max_rays(n, k);
  if (observed == expected) return "";
  if (observed == reference_max_rays(n, k + 1))
    return diagnosis("your prediction is that of depth k + 1: the levels are j = 0 (the camera ray) to k, k + 1 of them");
  if (k > 0 && observed == reference_max_rays(n, k - 1))
    return diagnosis("your prediction is that of depth k - 1: the sum runs over j = 0..k, the camera ray and k bounces");
  if (n > 1 && observed == power(n, k))
    return diagnosis("your prediction is N^k, the last level only: a sample traces every level, 1 + N + ... + N^k");
  if (n > 1 && observed == power(n, k + 1))
    return diagnosis("your prediction is N^(k+1): the geometric sum is (N^(k+1) - 1) / (N - 1), not its numerator");
  if (n == 1)
    return diagnosis(fmt::format("for N = 1 a sample traces k + 1 = {} rays (the closed form (N^(k+1) - 1) / (N - 1) "
                                 "divides by zero there)", k + 1));
  return diagnosis(fmt::format("{} instead of 1 + N + ... + N^k = {}", observed, expected));
}

/// (N, k) of a3.2's exact test: N = 1 (no closed form), small cases, and sums up to 2^63 - 1
/// (N = 2, k = 62), all below the saturation.
inline const std::vector<std::array<int, 2>> k_a3_prediction_cases{{1, 0}, {1, 4}, {1, 1000}, {2, 3}, {3, 2}, {4, 1},
                                                                   {7, 5}, {10, 9}, {2, 62}, {3, 39}};

/// (N, k) whose rays pass 2^64 - 1 (or reach it: N = 2, k = 63): the prediction saturates there.
inline const std::vector<std::array<int, 2>> k_a3_saturation_cases{{2, 63}, {2, 64}, {1000, 10}, {65536, 64}, {3, 1000}};

/// Exact: max_rays_per_sample(N, k) against the closed form for every case of `cases`.
template <class P>
TaskResult check_predicted_rays(P&& producer, const std::vector<std::array<int, 2>>& cases) {
  const std::vector<std::uint64_t> predicted = producer.predicted_rays(cases);
  TaskResult result{predicted.size() == cases.size(), ""};
  for (std::size_t i = 0; i < cases.size() && i < predicted.size(); ++i) {
    const auto [n, k] = cases[i];
    const std::uint64_t expected = reference_max_rays(static_cast<std::uint64_t>(n), k);
    const bool ok = predicted[i] == expected;
    result.passed = result.passed && ok;
    result.message += fmt::format("N = {}, k = {}: predicted {}, expected {}\n", n, k, predicted[i], expected);
    if (!ok) result.message += diagnose_prediction(predicted[i], static_cast<std::uint64_t>(n), k) + "\n";
  }
  return result;
}

/// A run too large to count must be refused, not started: chapter 04 compares N^k-sized
/// predictions with --max-rays, and a prediction that wraps round past 2^64 looks small.
template <class P>
TaskResult check_prediction_saturates(P&& producer) {
  TaskResult r = check_predicted_rays(producer, k_a3_saturation_cases);
  if (!r.passed)
    r.message += diagnosis("past 2^64 - 1 rays your prediction must stay at 2^64 - 1 (std::numeric_limits<std::uint64_t>::max()): "
                           "one that overflows wraps round to a small number, and chapter 04 would start a run it must refuse") + "\n";
  return r;
}

/// Exact: the prediction equals the rays your own recursion (a3.1) traces from the furnace's
/// centre, where no ray escapes.
template <class P>
TaskResult check_prediction_counts_your_recursion(P&& producer) {
  const std::vector<std::array<int, 2>> cases{{1, 3}, {2, 2}, {3, 3}, {5, 2}};
  const std::vector<std::uint64_t> predicted = producer.predicted_rays(cases);
  TaskResult result{predicted.size() == cases.size(), ""};
  for (std::size_t i = 0; i < cases.size() && i < predicted.size(); ++i) {
    const auto [n, k] = cases[i];
    const std::uint64_t traced =
        producer.recursive_single(0.5, 1.0, Vec3(0.0), Vec3(0.0, 0.0, 1.0), n, k, 11, static_cast<std::uint64_t>(100 + i)).rays;
    const bool ok = predicted[i] == traced;
    result.passed = result.passed && ok;
    result.message += fmt::format("N = {}, k = {}: predicted {}, your recursion traced {} (closed form {})\n", n, k,
                                  predicted[i], traced, reference_max_rays(static_cast<std::uint64_t>(n), k));
    if (!ok)
      result.message += diagnosis(predicted[i] == reference_max_rays(static_cast<std::uint64_t>(n), k)
                                      ? "your prediction is right and your recursion is not: see a3.1's ray-count test"
                                      : "your prediction and your recursion disagree: count the rays of each level") + "\n";
  }
  return result;
}

}  // namespace mcrt::testing::assignment
