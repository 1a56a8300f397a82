#pragma once
// What every assignment test shares: the fair statistical verdict (three seeds, a majority
// rejects) and the diagnoses that name a typical bug from the shape of a failure. The grader
// (scripts/grade) copies every line starting "DIAGNOSIS:" into the student's feedback.
//
// Fairness. A statistical task test runs its check at k_seeds = 3 independent seeds and fails
// only when at least 2 of them reject at alpha = k_seed_alpha = 5e-4. For a correct solution
// the p-values are independent and uniform, so it fails with probability
//   3 alpha^2 (1 - alpha) + alpha^3 = 7.5e-7  (< 1e-6, the course's promise).
// A known bug whose single-seed rejection probability is q >= 0.9995 fails with probability
// 3 q^2 (1 - q) + q^3 >= 0.999999; the bugs tested in tests/assignments/diagnosis_test.cpp give
// p-values below 1e-12 at every seed.

#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include <fmt/format.h>

namespace mcrt::testing::assignment {

inline constexpr int k_seeds = 3;
inline constexpr double k_seed_alpha = 5e-4;
inline constexpr std::array<std::uint64_t, k_seeds> k_grading_seeds{1009, 2029, 3037};

/// The probability that a correct solution fails a majority-of-three test.
constexpr double majority_false_failure_rate(double alpha = k_seed_alpha) {
  return 3.0 * alpha * alpha * (1.0 - alpha) + alpha * alpha * alpha;
}

/// The verdict of a test run at the k_seeds seeds: fails when at least 2 p-values < alpha.
struct SeedVerdict {
  std::array<double, k_seeds> p_values{};
  int rejections() const {
    int r = 0;
    for (double p : p_values) r += !(p >= k_seed_alpha);  // NaN rejects
    return r;
  }
  bool passed() const { return rejections() < 2; }
  std::string describe() const {
    return fmt::format("p-values at seeds {}, {}, {}: {:.3g}, {:.3g}, {:.3g} ({} of 3 below {})",
                       k_grading_seeds[0], k_grading_seeds[1], k_grading_seeds[2], p_values[0],
                       p_values[1], p_values[2], rejections(), k_seed_alpha);
  }
};

/// Runs `p_value(seed)` at each grading seed.
template <class PValue>
SeedVerdict at_grading_seeds(PValue&& p_value) {
  SeedVerdict v;
  for (int i = 0; i < k_seeds; ++i) v.p_values[i] = p_value(k_grading_seeds[i]);
  return v;
}

inline bool near(double x, double target, double relative) {
  return std::abs(x - target) <= relative * std::abs(target);
}

inline std::string diagnosis(const std::string& text) { return "DIAGNOSIS: " + text; }

/// A mean that is a simple multiple of the expected value usually is a missing or extra
/// factor: says which, or "" when the ratio is none of them.
inline std::string diagnose_mean_ratio(double observed, double expected) {
  if (!std::isfinite(observed))
    return diagnosis("your result is not finite (NaN or inf): a division by a pdf of 0?");
  const double r = observed / expected;
  const auto says = [&](const char* hint) {
    return diagnosis(fmt::format("your mean is {:.2f}x the expected value: {}", r, hint));
  };
  if (near(r, 2.0, 0.03)) return says("is your pdf off by a factor of 2?");
  if (near(r, 0.5, 0.03)) return says("is a factor of 2 missing (2 pi vs pi, or 2^(k-1) vs 2^k)?");
  if (near(r, 4.0, 0.03) || near(r, 0.25, 0.03))
    return says("is a factor of 4 (the area of the square [-1,1]^2) missing or extra?");
  if (near(r, 1.0 / 3.0, 0.03) || near(r, 3.0, 0.03))
    return says("is the length (b - a) of the interval missing or extra?");
  if (near(r, 1.0, 1e-3)) return "";
  return "";
}

/// Names the off-by-one of a recursion from its ray count (N branches, depth k), given the
/// expected count 1 + N + ... + N^k (the callers write it out: a kit ships this file, and the
/// sum is task a3.2's answer).
inline std::string diagnose_ray_count(std::uint64_t observed, std::uint64_t n, int k,
                                      std::uint64_t expected) {
  const auto power = [](std::uint64_t b, int e) {
    std::uint64_t r = 1;
    for (int i = 0; i < e; ++i) r *= b;
    return r;
  };
  if (observed == expected) return "";
  if (observed == expected + power(n, k + 1))
    return diagnosis(
        fmt::format("ray count is N^(k+1) = {} too many: does your recursion stop one bounce late?",
                    power(n, k + 1)));
  if (k > 0 && observed + power(n, k) == expected)
    return diagnosis(
        fmt::format("ray count is N^k = {} too few: does your recursion stop one bounce early?",
                    power(n, k)));
  if (observed + 1 == expected)
    return diagnosis("one ray too few: is the first (camera) ray counted?");
  if (observed == static_cast<std::uint64_t>(k) + 1)
    return diagnosis("ray count is k + 1, as if N = 1: do you loop over the N branches?");
  return diagnosis(
      fmt::format("ray count {} instead of 1 + N + ... + N^k = {}", observed, expected));
}

}  // namespace mcrt::testing::assignment
