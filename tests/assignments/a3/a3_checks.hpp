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

/// Exact: one call from the furnace's centre traces 1 + N + ... + N^k rays (none escapes),
/// written out for each (N, k).
template <class P>
TaskResult check_ray_counts(P&& producer) {
  TaskResult result{true, ""};
  struct Case {
    int n, k;
    std::uint64_t rays;
  };
  for (const auto& [n, k, expected] :
       std::vector<Case>{{1, 0, 1}, {1, 4, 5}, {2, 3, 15}, {3, 2, 13}, {4, 1, 5}}) {
    const std::uint64_t rays = producer
                                   .recursive_single(0.5, 1.0, Vec3(0.0), Vec3(0.0, 0.0, 1.0), n, k,
                                                     7, static_cast<std::uint64_t>(10 * n + k))
                                   .rays;
    const bool ok = rays == expected;
    result.passed = result.passed && ok;
    result.message += fmt::format("N = {}, k = {}: {} rays, expected {}\n", n, k, rays, expected);
    if (!ok)
      result.message += diagnose_ray_count(rays, static_cast<std::uint64_t>(n), k, expected) + "\n";
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
  const std::vector<double> values =
      producer.recursive_furnace(a, n_branches, k, samples, seed, 31);
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
      d = diagnosis(
          "each level weighs N a instead of a: is the sum over the N branches divided by N?");
    else if (near(mean, m.mean, 0.01) && variance > 1.2 * m.variance)
      d = diagnosis(fmt::format(
          "the mean is right but the variance is {:.2f}x the closed form: do the N branches share one direction (each needs its own)?",
          variance / m.variance));
    else if (near(mean, m.mean, 0.01))
      d = diagnosis(fmt::format("the mean is right but the variance is {:.2f}x the closed form",
                                variance / m.variance));
  }
  return {
      v.passed(),
      fmt::format(
          "furnace N = 2, k = 3, a = 0.5: mean {:.5f} (expected {:.5f}), variance {:.5f} (expected {:.5f}); {}\n{}",
          mean, m.mean, variance, m.variance, v.describe(), d)};
}

/// One case of a3.2's tests: N, k and the rays 1 + N + ... + N^k, written out (computed apart,
/// in exact integers): the public tests ship in the kit, so they hold numbers, not the formula.
struct PredictionCase {
  int n = 1;
  int k = 0;
  std::uint64_t rays = 0;
};

inline constexpr std::uint64_t k_most_rays = std::numeric_limits<std::uint64_t>::max();

/// a3.2's exact cases: N = 1 (no closed form), small cases, and sums up to 2^63 - 1 (N = 2,
/// k = 62), all below the saturation.
inline const std::vector<PredictionCase> k_a3_prediction_cases{{1, 0, 1},
                                                               {1, 4, 5},
                                                               {1, 1000, 1001},
                                                               {2, 3, 15},
                                                               {3, 2, 13},
                                                               {4, 1, 5},
                                                               {7, 5, 19608},
                                                               {10, 9, 1111111111},
                                                               {2, 62, 9223372036854775807ULL},
                                                               {3, 39, 6078832729528464400ULL}};

/// Cases whose rays reach 2^64 - 1 (N = 2, k = 63: exactly) or pass it: the prediction
/// saturates there.
inline const std::vector<PredictionCase> k_a3_saturation_cases{{2, 63, k_most_rays},
                                                               {2, 64, k_most_rays},
                                                               {1000, 10, k_most_rays},
                                                               {65536, 64, k_most_rays},
                                                               {3, 1000, k_most_rays}};

/// Names the classic mistakes of a ray-count prediction (N branches, depth k, `expected` rays),
/// by comparing in doubles (exact below 2^53, where every mistake shows as well).
inline std::string diagnose_prediction(std::uint64_t observed, std::uint64_t n, int k,
                                       std::uint64_t expected) {
  const double got = static_cast<double>(observed), want = static_cast<double>(expected);
  const double last = std::pow(static_cast<double>(n), k), next = last * static_cast<double>(n);
  if (observed == expected) return "";
  if (n == 1)
    return diagnosis(fmt::format(
        "for N = 1 a sample traces k + 1 = {} rays (the closed form (N^(k+1) - 1) / (N - 1) "
        "divides by zero there)",
        k + 1));
  if (want < 0x1p53 && got == want + next)
    return diagnosis(
        "your prediction is that of depth k + 1: the levels are j = 0 (the camera ray) to k, k + 1 of them");
  if (want < 0x1p53 && k > 0 && got == want - last)
    return diagnosis(
        "your prediction is that of depth k - 1: the sum runs over j = 0..k, the camera ray and k bounces");
  if (want < 0x1p53 && got == last)
    return diagnosis(
        "your prediction is N^k, the last level only: a sample traces every level, 1 + N + ... + N^k");
  if (want < 0x1p53 && got == next)
    return diagnosis(
        "your prediction is N^(k+1): the geometric sum is (N^(k+1) - 1) / (N - 1), not its numerator");
  return diagnosis(fmt::format("{} instead of 1 + N + ... + N^k = {}", observed, expected));
}

/// The producer's max_rays_per_sample(N, k) of every case, in order.
template <class P>
std::vector<std::uint64_t> predictions_of(P& producer, const std::vector<PredictionCase>& cases) {
  std::vector<std::array<int, 2>> calls;
  for (const PredictionCase& c : cases) calls.push_back({c.n, c.k});
  return producer.predicted_rays(calls);
}

/// Exact: max_rays_per_sample(N, k) against the rays of every case.
template <class P>
TaskResult check_predicted_rays(P&& producer, const std::vector<PredictionCase>& cases) {
  const std::vector<std::uint64_t> predicted = predictions_of(producer, cases);
  TaskResult result{predicted.size() == cases.size(), ""};
  for (std::size_t i = 0; i < cases.size() && i < predicted.size(); ++i) {
    const PredictionCase& c = cases[i];
    const bool ok = predicted[i] == c.rays;
    result.passed = result.passed && ok;
    result.message +=
        fmt::format("N = {}, k = {}: predicted {}, expected {}\n", c.n, c.k, predicted[i], c.rays);
    if (!ok)
      result.message +=
          diagnose_prediction(predicted[i], static_cast<std::uint64_t>(c.n), c.k, c.rays) + "\n";
  }
  return result;
}

/// A run too large to count must be refused, not started: chapter 04 compares N^k-sized
/// predictions with --max-rays, and a prediction that wraps round past 2^64 looks small.
template <class P>
TaskResult check_prediction_saturates(P&& producer) {
  TaskResult r = check_predicted_rays(producer, k_a3_saturation_cases);
  if (!r.passed)
    r.message +=
        diagnosis(
            "past 2^64 - 1 rays your prediction must stay at 2^64 - 1 (std::numeric_limits<std::uint64_t>::max()): "
            "one that overflows wraps round to a small number, and chapter 04 would start a run it must refuse") +
        "\n";
  return r;
}

/// Exact: the prediction equals the rays your own recursion (a3.1) traces from the furnace's
/// centre, where no ray escapes.
template <class P>
TaskResult check_prediction_counts_your_recursion(P&& producer) {
  const std::vector<PredictionCase> cases{{1, 3, 4}, {2, 2, 7}, {3, 3, 40}, {5, 2, 31}};
  const std::vector<std::uint64_t> predicted = predictions_of(producer, cases);
  TaskResult result{predicted.size() == cases.size(), ""};
  for (std::size_t i = 0; i < cases.size() && i < predicted.size(); ++i) {
    const PredictionCase& c = cases[i];
    const std::uint64_t traced =
        producer
            .recursive_single(0.5, 1.0, Vec3(0.0), Vec3(0.0, 0.0, 1.0), c.n, c.k, 11,
                              static_cast<std::uint64_t>(100 + i))
            .rays;
    const bool ok = predicted[i] == traced;
    result.passed = result.passed && ok;
    result.message +=
        fmt::format("N = {}, k = {}: predicted {}, your recursion traced {} (expected {})\n", c.n,
                    c.k, predicted[i], traced, c.rays);
    if (!ok)
      result.message +=
          diagnosis(
              predicted[i] == c.rays
                  ? "your prediction is right and your recursion is not: see a3.1's ray-count test"
                  : "your prediction and your recursion disagree: count the rays of each level") +
          "\n";
  }
  return result;
}

}  // namespace mcrt::testing::assignment
