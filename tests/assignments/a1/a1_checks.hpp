#pragma once
// The grading procedures of assignment a1 (Monte Carlo integration). They judge the answers
// of `p`, a Subject or an A1Producer (a1_produce.hpp): a1_disk, a1_ball, a1_monte_carlo,
// a1_trapezoid, each given its seed and stream (diagnosis_test.cpp: known-wrong variants).

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

inline constexpr std::uint64_t k_disk_points = 200000;  ///< sd of 4M/N: 0.0037

/// a1.1 at one seed: the p-value of 4M/N z-tested against pi with the closed-form sd
/// 4 sqrt(p(1-p)/N) (the estimate in `estimate`).
template <class P>
double disk_p_value(P&& producer, std::uint64_t seed, double& estimate) {
  estimate = producer.a1_disk(k_disk_points, seed, 11);
  return z_test_p_value(estimate, k_pi, disk_area_theory_std(k_disk_points));
}

/// a1.1: E[4M/N] = pi, disk_p_value at three seeds.
template <class P>
TaskResult check_disk_estimator(P&& producer) {
  double sum = 0.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    double a = 0.0;
    const double p = disk_p_value(producer, seed, a);
    sum += a;
    return p;
  });
  const double mean = sum / k_seeds;
  std::string d = diagnose_mean_ratio(mean, k_pi);
  if (near(mean, 4.0 / std::sqrt(2.0), 0.01))
    d = diagnosis("your estimate is 4/sqrt(2) = 2.83: is y drawn equal to x (the test 2 x^2 <= 1)?");
  else if (near(mean, k_pi / 4.0, 0.01))
    d = diagnosis("your estimate is about pi/4: you forgot the factor 4 (the area of the square [-1,1]^2)");
  return {v.passed(), fmt::format("disk estimate, mean over 3 seeds {:.5f} (pi = {:.5f}); {}\n{}",
                                  mean, k_pi, v.describe(), v.passed() ? "" : d)};
}

inline constexpr std::uint64_t k_ball_points = 100000;

/// a1.2 at one seed: the p-value of 2^k M/N z-tested against V_k with the closed-form sd
/// (the estimate in `volume`).
template <class P>
double ball_p_value(P&& producer, int k, std::uint64_t seed, double& volume) {
  volume = producer.a1_ball(k, k_ball_points, seed, 12);
  return z_test_p_value(volume, unit_ball_volume(k), ball_volume_theory_std(k, k_ball_points));
}

/// a1.2 at one seed, every dimension of `dims` at once: the Sidak combination of their
/// ball_p_values, so that the task holds one verdict (fails a correct solution with
/// probability 7.5e-7, grading.hpp) rather than one per dimension. Adds each estimate to
/// `volume_sums`.
template <class P>
double balls_p_value(P&& producer, const std::vector<int>& dims, std::uint64_t seed,
                     std::vector<double>& volume_sums) {
  volume_sums.resize(dims.size(), 0.0);
  std::vector<double> p(dims.size());
  for (std::size_t i = 0; i < dims.size(); ++i) {
    double volume = 0.0;
    p[i] = ball_p_value(producer, dims[i], seed, volume);
    volume_sums[i] += volume;
  }
  return sidak_p_value(p);
}

/// a1.2: E[2^k M/N] = V_k for k = `dims`, balls_p_value at three seeds.
template <class P>
TaskResult check_ball_estimator(P&& producer, const std::vector<int>& dims) {
  std::vector<double> sums;
  const SeedVerdict v = at_grading_seeds(
      [&](std::uint64_t seed) { return balls_p_value(producer, dims, seed, sums); });
  TaskResult result{v.passed(), ""};
  for (std::size_t i = 0; i < dims.size(); ++i) {
    const int k = dims[i];
    const double mean = sums[i] / k_seeds;
    std::string d = diagnose_mean_ratio(mean, unit_ball_volume(k));
    if (near(mean, unit_ball_volume(k) / 2.0, 0.02))
      d = diagnosis("your volume is half of V_k: is M/N scaled by 2^(k-1) instead of 2^k?");
    result.message += fmt::format("k = {}: mean {:.5f}, V_k = {:.5f}\n{}", k, mean,
                                  unit_ball_volume(k), v.passed() || d.empty() ? "" : d + "\n");
  }
  result.message += "all dimensions at once (Sidak): " + v.describe() + "\n";
  return result;
}

inline constexpr std::uint64_t k_basic_points = 10000;

/// a1.3's F_N of x^2 on [1, 4]: I = 21, and the closed-form sd sqrt((vol J - I^2) / N) with
/// vol J - I^2 = 172.8.
inline double basic_estimator_theory_sd() { return std::sqrt(172.8 / static_cast<double>(k_basic_points)); }

/// a1.3 at one seed: the p-value of F_N z-tested against I = 21 (the estimate and its standard
/// error in `e`).
template <class P>
double basic_estimator_p_value(P&& producer, std::uint64_t seed, EstimateAndError& e) {
  e = producer.a1_monte_carlo(A1Integrand::square, 0.0, Segment{1.0, 4.0}, k_basic_points, seed, 13);
  return z_test_p_value(e.estimate, 21.0, basic_estimator_theory_sd());
}

/// a1.3: F_N = (b - a)/N sum f(X_i) for f = x^2 on [1, 4]: basic_estimator_p_value at three
/// seeds, and the standard error within 10% of the theory (its relative sd is about 1% at
/// N = 10^4).
template <class P>
TaskResult check_basic_estimator(P&& producer) {
  const double integral = 21.0, theory_sd = basic_estimator_theory_sd();
  double sum = 0.0;
  bool se_ok = true;
  std::string se_note;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    EstimateAndError e;
    const double p = basic_estimator_p_value(producer, seed, e);
    sum += e.estimate;
    if (!near(e.standard_error, theory_sd, 0.1)) {
      se_ok = false;
      se_note = fmt::format("standard_error {:.4g}, expected about vol * s / sqrt(N) = {:.4g}",
                            e.standard_error, theory_sd);
    }
    return p;
  });
  const double mean = sum / k_seeds;
  const bool passed = v.passed() && se_ok;
  return {passed, fmt::format("F_N of x^2 on [1, 4]: mean {:.5f} (I = 21); {}\n{}{}", mean,
                              v.describe(), se_note,
                              v.passed() ? std::string() : fmt::format("\n{}", diagnose_mean_ratio(mean, integral)))};
}

/// a1.4: the trapezoid rule on exp(-x^2) over [0, 1]: its error must fall as h^2 (ratio 4
/// when n - 1 doubles; 2 would be O(h), the end points' half weights forgotten) and be close to
/// the leading term h^2 (f'(b) - f'(a)) / 12 (Euler-Maclaurin). Deterministic: the
/// tolerance 2% covers the next term, O(h^4).
template <class P>
TaskResult check_trapezoid(P&& producer) {
  const Gaussian1D f;
  const auto rule = [&](std::uint64_t n) { return producer.a1_trapezoid(A1Integrand::gaussian, 0.0, f.domain, n); };
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
    result.message += fmt::format("n = {}: T_n - I = {:.3e}, expected about {:.3e}; ratio to n = {}: {:.2f}\n",
                                  n, error, leading, 2 * n - 1, error / next_error);
    if (!ok && near(error / next_error, 2.0, 0.1))
      result.message += diagnosis("your error falls as h, not h^2: do the two end points weigh h/2?") + "\n";
    else if (!ok && near(error / next_error, 4.0, 0.1))
      result.message += diagnosis("the error falls as h^2 but its size is wrong: is h = (b - a)/(n - 1) (n points make n - 1 intervals)?") + "\n";
  }
  return result;
}

}  // namespace mcrt::testing::assignment
