#pragma once
// The grading procedures of assignment a1 (Monte Carlo integration). They judge the answers
// of `p`, a Subject or an A1Producer (a1_produce.hpp): a1_disk, a1_ball, a1_monte_carlo,
// a1_trapezoid, each given its seed and stream (diagnosis_test.cpp: known-wrong variants).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "assignments/a1/a1_produce.hpp"
#include "assignments/grading.hpp"
#include "core/rng.hpp"
#include "integration/ball.hpp"
#include "integration/disk_area.hpp"
#include "integration/domain.hpp"
#include "integration/integrands.hpp"
#include "integration/monte_carlo.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

/// A task check's outcome: what a student reads when it fails.
struct TaskResult {
  bool passed = false;
  std::string message;
};

// Monte Carlo checked as Monte Carlo: each estimator task is graded on its spread too. At a
// grading seed, k_spread_runs independent runs of the estimator (streams k_spread_stream + r),
// each of k_spread_points points, give estimates X_r whose sample variance s^2 is tested
// against the closed form sigma^2 (the disk: 16 eta (1 - eta) / N with eta = pi/4; the k-ball:
// 4^k p (1 - p) / N with p = V_k / 2^k; F_N: (vol J - I^2) / N) by the two-sided chi-square
// test (R - 1) s^2 / sigma^2 ~ chi^2(R - 1). An answer that draws no random number (the
// multiple of 4/N nearest pi, expected counts, midpoint quadrature) has s^2 = 0 and rejects
// at every seed; runs that share their points or use fewer than N reject the other way.
// Tolerance: the chi-square law is exact for normal X_r; a mean of N = 1000 Bernoulli (or
// x^2) terms has excess kurtosis kappa = (1 - 6 p q) / (N p q) (or -1.07 / N) of at most
// 2e-3 in absolute value (k = 3), which scales Var[s^2] by 1 + kappa (R - 1) / (2R): a part
// in 1000, so the test rejects a correct estimator at its stated alpha (k_seed_alpha).
inline constexpr int k_spread_runs = 200;
inline constexpr std::uint64_t k_spread_points = 1000;
inline constexpr std::uint64_t k_spread_stream = 1000;

/// The spread of one estimator's runs at one seed.
struct Spread {
  double p_value = 1.0;  ///< the chi-square test of s^2 against sigma^2
  double ratio = 1.0;    ///< s^2 / sigma^2 (0: every run gave the same number)
  double first = 0.0;    ///< the first run's estimate
};

/// `run(stream)` for the k_spread_runs streams, s^2 tested against `sigma2`.
template <class Run>
Spread spread_of_runs(Run&& run, double sigma2) {
  std::vector<double> x(k_spread_runs);
  double sum = 0.0;
  for (int r = 0; r < k_spread_runs; ++r) {
    x[static_cast<std::size_t>(r)] = run(k_spread_stream + static_cast<std::uint64_t>(r));
    sum += x[static_cast<std::size_t>(r)];
  }
  const double mean = sum / k_spread_runs;
  double squares = 0.0;
  for (double v : x) squares += (v - mean) * (v - mean);
  // Runs that all gave one number have s^2 = 0 exactly (the sum above can leave a round-off).
  const bool all_equal = std::all_of(x.begin(), x.end(), [&](double v) { return v == x[0]; });
  const double s2 = all_equal ? 0.0 : squares / (k_spread_runs - 1);
  if (!std::isfinite(s2)) return {0.0, s2, x[0]};
  return {variance_test_p_value(s2, static_cast<std::uint64_t>(k_spread_runs), sigma2), s2 / sigma2,
          x[0]};
}

/// Says why a spread failed (`ratio`: s^2 / sigma^2 averaged over the seeds; `closed_form`:
/// sigma^2 as the handout writes it), or "" when `rejected` (a majority of seeds) is false.
inline std::string diagnose_spread(bool rejected, double ratio, double first,
                                   const std::string& closed_form) {
  if (!rejected) return "";
  if (ratio == 0.0)
    return diagnosis(fmt::format(
        "zero spread: not a Monte Carlo estimate. {} runs of N = {} points at different seeds all gave {:.9g}, "
        "where independent random points vary with variance {}: is your answer computed without the random "
        "numbers (a closed form, expected counts, a grid)?",
        k_spread_runs, k_spread_points, first, closed_form));
  if (ratio < 1.0)
    return diagnosis(fmt::format(
        "too small spread: not a Monte Carlo estimate of N independent points. Over {} runs of N = {} points at "
        "different seeds the variance is {:.3g}x the closed form {}: are your points random and independent (not a "
        "grid, not stratified), N of them (not more)?",
        k_spread_runs, k_spread_points, ratio, closed_form));
  return diagnosis(fmt::format(
      "too large spread: over {} runs of N = {} points at different seeds the variance is {:.3g}x the closed form "
      "{}: are all N points used, each drawn anew (not repeated, not fewer than N)?",
      k_spread_runs, k_spread_points, ratio, closed_form));
}

/// A task's outcome at one seed: its mean's z-test and its spread, one p-value for the verdict.
struct SeedOutcome {
  double p_mean = 1.0;
  Spread spread;
  /// Sidak of the mean's and the spread's p-values: one verdict per seed, uniform for a correct
  /// estimator (the mean and s^2 of normal runs are independent).
  double p_value() const { return sidak_p_value(std::vector<double>{p_mean, spread.p_value}); }
};

inline constexpr std::uint64_t k_disk_points = 200000;  ///< sd of 4M/N: 0.0037

/// sigma^2 of 4M/N: 16 eta (1 - eta) / N with eta = pi/4.
inline double disk_variance(std::uint64_t n) {
  return 16.0 * k_disk_hit_probability * (1.0 - k_disk_hit_probability) / static_cast<double>(n);
}

/// a1.1 at one seed: 4M/N z-tested against pi with the closed-form sd 4 sqrt(p(1-p)/N) (the
/// estimate in `estimate`), and the spread of k_spread_runs runs.
template <class P>
SeedOutcome disk_outcome(P&& producer, std::uint64_t seed, double& estimate) {
  estimate = producer.a1_disk(k_disk_points, seed, 11);
  SeedOutcome o;
  o.p_mean = z_test_p_value(estimate, k_pi, disk_area_theory_std(k_disk_points));
  o.spread = spread_of_runs(
      [&](std::uint64_t stream) { return producer.a1_disk(k_spread_points, seed, stream); },
      disk_variance(k_spread_points));
  return o;
}

/// a1.1 at one seed: disk_outcome's one p-value.
template <class P>
double disk_p_value(P&& producer, std::uint64_t seed, double& estimate) {
  return disk_outcome(producer, seed, estimate).p_value();
}

/// Whether a majority of the seeds rejected, from their p-values.
inline bool majority_rejects(const std::array<double, k_seeds>& p) {
  SeedVerdict v;
  v.p_values = p;
  return !v.passed();
}

/// a1.1: E[4M/N] = pi and V[4M/N] = 16 eta (1 - eta)/N, disk_outcome at three seeds.
template <class P>
TaskResult check_disk_estimator(P&& producer) {
  double sum = 0.0, ratios = 0.0, first = 0.0;
  std::array<double, k_seeds> p_mean{}, p_spread{};
  int i = 0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    double a = 0.0;
    const SeedOutcome o = disk_outcome(producer, seed, a);
    sum += a;
    ratios += o.spread.ratio;
    first = o.spread.first;
    p_mean[static_cast<std::size_t>(i)] = o.p_mean;
    p_spread[static_cast<std::size_t>(i++)] = o.spread.p_value;
    return o.p_value();
  });
  const double mean = sum / k_seeds;
  std::string d = diagnose_mean_ratio(mean, k_pi);
  if (near(mean, 4.0 / std::sqrt(2.0), 0.01))
    d = diagnosis(
        "your estimate is 4/sqrt(2) = 2.83: is y drawn equal to x (the test 2 x^2 <= 1)?");
  else if (near(mean, k_pi / 4.0, 0.01))
    d = diagnosis(
        "your estimate is about pi/4: you forgot the factor 4 (the area of the square [-1,1]^2)");
  if (d.empty() && !majority_rejects(p_mean))
    d = diagnose_spread(majority_rejects(p_spread), ratios / k_seeds, first,
                        "16 eta (1 - eta) / N, eta = pi/4");
  return {v.passed(),
          fmt::format(
              "disk estimate, mean over 3 seeds {:.5f} (pi = {:.5f}); spread over {} runs {:.3g}x "
              "16 eta (1 - eta) / N; {}\n{}",
              mean, k_pi, k_spread_runs, ratios / k_seeds, v.describe(), v.passed() ? "" : d)};
}

inline constexpr std::uint64_t k_ball_points = 100000;

/// sigma^2 of 2^k M/N: 4^k p (1 - p) / N with p = V_k / 2^k.
inline double ball_variance(int k, std::uint64_t n) {
  const double sd = ball_volume_theory_std(k, n);
  return sd * sd;
}

/// a1.2 at one seed: 2^k M/N z-tested against V_k with the closed-form sd (the estimate in
/// `volume`), and the spread of k_spread_runs runs.
template <class P>
SeedOutcome ball_outcome(P&& producer, int k, std::uint64_t seed, double& volume) {
  volume = producer.a1_ball(k, k_ball_points, seed, 12);
  SeedOutcome o;
  o.p_mean = z_test_p_value(volume, unit_ball_volume(k), ball_volume_theory_std(k, k_ball_points));
  o.spread = spread_of_runs(
      [&](std::uint64_t stream) { return producer.a1_ball(k, k_spread_points, seed, stream); },
      ball_variance(k, k_spread_points));
  return o;
}

/// a1.2 at one seed, every dimension of `dims` at once: the Sidak combination of their
/// ball_outcomes (mean and spread), so that the task holds one verdict (fails a correct
/// solution with probability 7.5e-7, grading.hpp) rather than one per dimension. Adds each
/// estimate to `volume_sums`; each dimension's outcome to `outcomes` if given.
template <class P>
double balls_p_value(P&& producer, const std::vector<int>& dims, std::uint64_t seed,
                     std::vector<double>& volume_sums,
                     std::vector<SeedOutcome>* outcomes = nullptr) {
  volume_sums.resize(dims.size(), 0.0);
  std::vector<double> p;
  for (std::size_t i = 0; i < dims.size(); ++i) {
    double volume = 0.0;
    const SeedOutcome o = ball_outcome(producer, dims[i], seed, volume);
    p.push_back(o.p_mean);
    p.push_back(o.spread.p_value);
    volume_sums[i] += volume;
    if (outcomes) outcomes->push_back(o);
  }
  return sidak_p_value(p);
}

/// a1.2: E[2^k M/N] = V_k and V[2^k M/N] = 4^k p (1 - p)/N for k = `dims`, balls_p_value at
/// three seeds.
template <class P>
TaskResult check_ball_estimator(P&& producer, const std::vector<int>& dims) {
  std::vector<double> sums;
  std::vector<std::vector<SeedOutcome>> by_seed;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    by_seed.emplace_back();
    return balls_p_value(producer, dims, seed, sums, &by_seed.back());
  });
  TaskResult result{v.passed(), ""};
  for (std::size_t i = 0; i < dims.size(); ++i) {
    const int k = dims[i];
    const double mean = sums[i] / k_seeds;
    std::array<double, k_seeds> p_mean{}, p_spread{};
    double ratios = 0.0;
    for (std::size_t s = 0; s < k_seeds; ++s) {
      p_mean[s] = by_seed[s][i].p_mean;
      p_spread[s] = by_seed[s][i].spread.p_value;
      ratios += by_seed[s][i].spread.ratio;
    }
    std::string d = diagnose_mean_ratio(mean, unit_ball_volume(k));
    if (near(mean, unit_ball_volume(k) / 2.0, 0.02))
      d = diagnosis("your volume is half of V_k: is M/N scaled by 2^(k-1) instead of 2^k?");
    if (d.empty() && !majority_rejects(p_mean))
      d = diagnose_spread(majority_rejects(p_spread), ratios / k_seeds, by_seed[0][i].spread.first,
                          "4^k p (1 - p) / N, p = V_k / 2^k");
    result.message += fmt::format(
        "k = {}: mean {:.5f}, V_k = {:.5f}; spread over {} runs {:.3g}x 4^k p (1 - p) / N\n{}", k,
        mean, unit_ball_volume(k), k_spread_runs, ratios / k_seeds,
        v.passed() || d.empty() ? "" : d + "\n");
  }
  result.message += "all dimensions, mean and spread at once (Sidak): " + v.describe() + "\n";
  return result;
}

inline constexpr std::uint64_t k_basic_points = 10000;

/// a1.3's F_N of x^2 on [1, 4]: I = 21, and the closed-form sd sqrt((vol J - I^2) / N) with
/// vol J - I^2 = 172.8.
inline double basic_estimator_theory_sd() {
  return std::sqrt(172.8 / static_cast<double>(k_basic_points));
}

/// a1.3 at one seed: F_N z-tested against I = 21 (the estimate and its standard error in
/// `e`), and the spread of k_spread_runs runs against (vol J - I^2) / N.
template <class P>
SeedOutcome basic_estimator_outcome(P&& producer, std::uint64_t seed, EstimateAndError& e) {
  e = producer.a1_monte_carlo(A1Integrand::square, 0.0, Segment{1.0, 4.0}, k_basic_points, seed,
                              13);
  SeedOutcome o;
  o.p_mean = z_test_p_value(e.estimate, 21.0, basic_estimator_theory_sd());
  o.spread = spread_of_runs(
      [&](std::uint64_t stream) {
        return producer
            .a1_monte_carlo(A1Integrand::square, 0.0, Segment{1.0, 4.0}, k_spread_points, seed,
                            stream)
            .estimate;
      },
      172.8 / static_cast<double>(k_spread_points));
  return o;
}

/// a1.3 at one seed: basic_estimator_outcome's one p-value.
template <class P>
double basic_estimator_p_value(P&& producer, std::uint64_t seed, EstimateAndError& e) {
  return basic_estimator_outcome(producer, seed, e).p_value();
}

/// a1.3: F_N = (b - a)/N sum f(X_i) for f = x^2 on [1, 4]: basic_estimator_outcome at three
/// seeds (mean and spread), and the standard error within 10% of the theory (its relative sd
/// is about 1% at N = 10^4).
template <class P>
TaskResult check_basic_estimator(P&& producer) {
  const double integral = 21.0, theory_sd = basic_estimator_theory_sd();
  double sum = 0.0, ratios = 0.0, first = 0.0;
  bool se_ok = true;
  std::string se_note;
  std::array<double, k_seeds> p_mean{}, p_spread{};
  int i = 0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    EstimateAndError e;
    const SeedOutcome o = basic_estimator_outcome(producer, seed, e);
    sum += e.estimate;
    ratios += o.spread.ratio;
    first = o.spread.first;
    p_mean[static_cast<std::size_t>(i)] = o.p_mean;
    p_spread[static_cast<std::size_t>(i++)] = o.spread.p_value;
    if (!near(e.standard_error, theory_sd, 0.1)) {
      se_ok = false;
      se_note = fmt::format("standard_error {:.4g}, expected about vol * s / sqrt(N) = {:.4g}\n",
                            e.standard_error, theory_sd);
    }
    return o.p_value();
  });
  const double mean = sum / k_seeds;
  const bool passed = v.passed() && se_ok;
  std::string d = diagnose_mean_ratio(mean, integral);
  if (d.empty() && !majority_rejects(p_mean))
    d = diagnose_spread(majority_rejects(p_spread), ratios / k_seeds, first,
                        "(vol J - I^2) / N = 172.8 / N");
  return {
      passed,
      fmt::format(
          "F_N of x^2 on [1, 4]: mean {:.5f} (I = 21); spread over {} runs {:.3g}x (vol J - I^2) / N; "
          "{}\n{}{}",
          mean, k_spread_runs, ratios / k_seeds, v.describe(), se_note, v.passed() ? "" : d)};
}

/// a1.4: the trapezoid rule on exp(-x^2) over [0, 1]: its error must fall as h^2 (ratio 4
/// when n - 1 doubles; 2 would be O(h), the end points' half weights forgotten) and be close to
/// the leading term h^2 (f'(b) - f'(a)) / 12 (Euler-Maclaurin). Deterministic: the
/// tolerance 2% covers the next term, O(h^4).
template <class P>
TaskResult check_trapezoid(P&& producer) {
  const Gaussian1D f;
  const auto rule = [&](std::uint64_t n) {
    return producer.a1_trapezoid(A1Integrand::gaussian, 0.0, f.domain, n);
  };
  const double integral = f.reference();
  const double fprime_b = -2.0 * std::exp(-1.0), fprime_a = 0.0;
  TaskResult result{true, ""};
  for (std::uint64_t n : {9u, 17u, 33u}) {
    const double h = 1.0 / static_cast<double>(n - 1);
    const double error = rule(n) - integral;
    const double leading = h * h * (fprime_b - fprime_a) / 12.0;
    const double next_error = rule(2 * n - 1) - integral;
    const bool ok = near(error, leading, 0.02);
    result.passed = result.passed && ok;
    result.message +=
        fmt::format("n = {}: T_n - I = {:.3e}, expected about {:.3e}; ratio to n = {}: {:.2f}\n", n,
                    error, leading, 2 * n - 1, error / next_error);
    if (!ok && near(error / next_error, 2.0, 0.1))
      result.message +=
          diagnosis("your error falls as h, not h^2: do the two end points weigh h/2?") + "\n";
    else if (!ok && near(error / next_error, 4.0, 0.1))
      result.message +=
          diagnosis(
              "the error falls as h^2 but its size is wrong: is h = (b - a)/(n - 1) (n points make n - 1 intervals)?") +
          "\n";
  }
  return result;
}

}  // namespace mcrt::testing::assignment
