#pragma once
// The grading procedures of assignment a7 (stratified sampling). Each judges what a producer
// returns (a Subject: the student's code in-process or in the subject program;
// diagnosis_test.cpp: known-wrong variants):
//   a7.1 jittered points: one point in each cell of the k x k grid (exact, at three keys), a
//        point uniform on [0,1)^2 over randomisations (chi-square), and the variance of a smooth
//        integrand's estimate falling faster than Monte Carlo's (a variance ratio);
//   a7.2 Latin hypercube points: one point in each of the n slabs of every dimension (exact),
//        two dimensions of a point jointly uniform over randomisations (chi-square);
//   a7.3 the radical inverse: phi_b(0) = 0 and phi_b(b i + d) = (d + phi_b(i)) / b, which
//        define it (exact, to rounding);
//   a7.4 scrambled Halton points: one point in each box of 2^a x 3^b at n = 2^a 3^b (exact), a
//        point uniform on [0,1)^2 over randomisations (chi-square): what makes it unbiased.
// An exact check must pass at every grading seed; a statistical one fails on a majority of
// three seeds at 5e-4 (grading.hpp: a correct solution fails with probability 7.5e-7).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assignments/a1/a1_checks.hpp"  // TaskResult
#include "assignments/grading.hpp"
#include "assignments/subject/requests.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

// ---------------------------------------------------------------- the sizes graded

/// a7.1: the jittered grid's side (n = k^2 points) of the public tests.
inline constexpr std::uint32_t k_a7_grid = 8;
/// a7.2: Latin hypercube points and dimensions (n not a power of two, d > 2 so that a reused
/// permutation has several dimensions to repeat in).
inline constexpr std::uint32_t k_a7_latin_n = 20;
inline constexpr unsigned k_a7_latin_dims = 5;
/// a7.4: n = 72 = 2^3 3^2: dimensions 0 and 1 (bases 2 and 3) put one point in each of the 8 x 9
/// boxes [a/8, (a+1)/8) x [b/9, (b+1)/9).
inline constexpr std::uint32_t k_a7_halton_n = 72;
/// The chi-square of one point over randomisations: 16 x 16 cells (finer than every grid above,
/// so a point's place within its stratum is tested too), 40 keys expected per cell.
inline constexpr unsigned k_a7_cells = 16;
inline constexpr std::uint32_t k_a7_uniform_keys = k_a7_cells * k_a7_cells * 40;
/// a7.1's rate test: randomisations per grid size.
inline constexpr std::uint32_t k_a7_rate_keys = 400;

/// The first key of a seed's randomisations: seed 2^21. Seeds below 2^32 (a variant's hidden
/// seed included) never share a key (a check uses fewer than 2^21), and every key stays below
/// 2^53, as a request's numbers must (requests.hpp: they travel as doubles).
inline std::uint64_t a7_first_key(std::uint64_t seed) { return seed << 21; }

inline std::vector<std::uint32_t> a7_indices(std::uint32_t n) {
  std::vector<std::uint32_t> out(n);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = i;
  return out;
}

// ---------------------------------------------------------------- exact stratification

/// The stratum of point i in dimensions a (cells_a cells) and b (cells_b; a = b with cells_b = 1
/// for slabs of one dimension): "" when each of the cells_a x cells_b strata holds exactly one
/// of the n points (n = cells_a cells_b), else what is wrong. `values`: n points of d numbers.
inline std::string strata_problem(const std::vector<double>& values, std::uint32_t n, unsigned d,
                                  unsigned a, std::uint32_t cells_a, unsigned b,
                                  std::uint32_t cells_b) {
  std::vector<std::uint32_t> count(std::size_t{cells_a} * cells_b, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double x = values[std::size_t{i} * d + a], y = values[std::size_t{i} * d + b];
    if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0))
      return fmt::format("point {} has coordinates {}, {} in dimensions {} and {}: outside [0,1)",
                         i, x, y, a, b);
    const auto sa = std::min(static_cast<std::uint32_t>(x * cells_a), cells_a - 1);
    const auto sb = std::min(static_cast<std::uint32_t>(y * cells_b), cells_b - 1);
    ++count[std::size_t{sa} * cells_b + sb];
  }
  const auto crowded = std::find_if(count.begin(), count.end(), [](auto c) { return c > 1; });
  if (crowded == count.end()) return "";
  const auto at = static_cast<std::size_t>(crowded - count.begin());
  const auto empty = std::count(count.begin(), count.end(), 0u);
  return fmt::format(
      "stratum ({}, {}) of the {} x {} in dimensions {}, {} holds {} points and {} "
      "strata hold none",
      at / cells_b, at % cells_b, cells_a, cells_b, a, b, *crowded, empty);
}

/// Runs `problem(key0)` at every grading seed: an exact check passes at all of them.
template <class Problem>
TaskResult exact_at_every_seed(Problem&& problem, const std::string& hint) {
  for (std::uint64_t seed : k_grading_seeds) {
    const std::string p = problem(a7_first_key(seed));
    if (!p.empty()) return {false, fmt::format("key {}: {}\n{}", a7_first_key(seed), p, hint)};
  }
  return {true, ""};
}

/// a7.1: one point per cell of the k x k grid of every pair of dimensions (d even), at 3 keys.
template <class S>
TaskResult check_jittered_strata(S& subject, std::uint32_t k = k_a7_grid, unsigned d = 2) {
  const std::uint32_t n = k * k;
  return exact_at_every_seed(
      [&](std::uint64_t key) {
        const std::vector<double> v =
            subject.a7_points(A7PointSet::jittered, n, d, key, 1, a7_indices(n));
        for (unsigned a = 0; a + 1 < d; a += 2) {
          const std::string p = strata_problem(v, n, d, a, k, a + 1, k);
          if (!p.empty()) return p;
        }
        return std::string();
      },
      diagnosis("a jitter outside its stratum: point i must lie in its own cell, x = (column + "
                "u) / k and y = (row + v) / k with u, v in [0, 1), and the n cells each hold one"));
}

/// a7.2: one point in each of the n slabs [m/n, (m+1)/n) of every dimension, at 3 keys.
template <class S>
TaskResult check_latin_slabs(S& subject, std::uint32_t n = k_a7_latin_n,
                             unsigned d = k_a7_latin_dims) {
  return exact_at_every_seed(
      [&](std::uint64_t key) {
        const std::vector<double> v =
            subject.a7_points(A7PointSet::latin_hypercube, n, d, key, 1, a7_indices(n));
        for (unsigned j = 0; j < d; ++j) {
          const std::string p = strata_problem(v, n, d, j, n, j, 1);
          if (!p.empty()) return p;
        }
        return std::string();
      },
      diagnosis("each dimension's n slabs must hold one point each: x_j = (pi_j(i) + u) / n with "
                "pi_j a permutation of 0..n-1 and u in [0, 1)"));
}

/// a7.4: at n = 2^a 3^b, one point in each of the 2^a x 3^b boxes of dimensions 0 and 1, at 3
/// keys.
template <class S>
TaskResult check_halton_boxes(S& subject, std::uint32_t cells_0 = 8, std::uint32_t cells_1 = 9) {
  const std::uint32_t n = cells_0 * cells_1;
  return exact_at_every_seed(
      [&](std::uint64_t key) {
        const std::vector<double> v =
            subject.a7_points(A7PointSet::halton, n, 2, key, 1, a7_indices(n));
        return strata_problem(v, n, 2, 0, cells_0, 1, cells_1);
      },
      diagnosis(
          "the first digits of phi_2(i) and phi_3(i) must stay a one-to-one image of i's last "
          "digits: permute the digits, position by position, with permutations of 0..b-1"));
}

// ---------------------------------------------------------------- a7.3 the radical inverse

/// The bases and indices of a7.3's public test: phi_b(i) for every i < 2000.
inline constexpr std::uint32_t k_a7_radical_indices = 2000;

/// phi_b(0) = 0 and phi_b(b i + d) = (d + phi_b(i)) / b for every b i + d below the indices
/// asked: the two define phi_b. Tolerance 1e-14: both sides are a few roundings (1.1e-16 each)
/// from the exact value, while a wrong digit moves it by b^-K >= 1/2000 at these indices.
template <class S>
TaskResult check_radical_inverse(S& subject, const std::vector<std::uint32_t>& bases) {
  for (std::uint32_t b : bases) {
    const std::vector<double> phi = subject.a7_radical_inverse(b, a7_indices(k_a7_radical_indices));
    if (phi.size() != k_a7_radical_indices) return {false, "wrong number of values"};
    for (std::uint32_t i = 0; i < k_a7_radical_indices; ++i)
      if (!(phi[i] >= 0.0 && phi[i] < 1.0))
        return {false, fmt::format("phi_{}({}) = {}: outside [0, 1)", b, i, phi[i])};
    if (phi[0] != 0.0) return {false, fmt::format("phi_{}(0) = {}, not 0", b, phi[0])};
    if (phi[b] == phi[1])
      return {false, fmt::format("phi_{0}({0}) = phi_{0}(1) = {1}\n{2}", b, phi[1],
                                 diagnosis("the digits are in the wrong order: i's least "
                                           "significant digit comes first after the point, "
                                           "phi_b(b) = 1/b^2 and phi_b(1) = 1/b"))};
    for (std::uint32_t i = 0; b * i < k_a7_radical_indices; ++i)
      for (std::uint32_t d = 0; d < b && b * i + d < k_a7_radical_indices; ++d) {
        const double expected = (d + phi[i]) / b;
        if (!(std::abs(phi[b * i + d] - expected) <= 1e-14))
          return {false,
                  fmt::format("phi_{0}({1}) = {2}, but phi_{0}({3}) = {4} gives ({5} + {4}) / "
                              "{0} = {6}\n{7}",
                              b, b * i + d, phi[b * i + d], i, phi[i], d, expected,
                              diagnosis("appending a digit d to i must give (d + "
                                        "phi_b(i)) / b: mirror every digit of i"))};
      }
  }
  return {true, ""};
}

// ---------------------------------------------------------------- uniformity over keys

/// The chi-square p-value of point `index`'s dimensions (a, b) over k_a7_uniform_keys keys
/// from a7_first_key(seed): 16 x 16 equal cells, each expected 40 (the chi-square law with 255
/// degrees of freedom holds well there). A coordinate outside [0, 1) or not finite gives 0.
/// `same` counts the keys whose point equals the first key's (an unscrambled set: all of them),
/// `same_slab` those whose dimensions a and b lie in the same of `slabs` slabs.
struct UniformityResult {
  double p_value = 0.0;
  std::uint32_t same = 0, same_slab = 0;
};
template <class S>
UniformityResult point_uniformity(S& subject, A7PointSet kind, std::uint32_t n, unsigned d,
                                  std::uint32_t index, unsigned a, unsigned b, std::uint64_t seed,
                                  std::uint32_t slabs = 1) {
  const std::vector<double> v =
      subject.a7_points(kind, n, d, a7_first_key(seed), k_a7_uniform_keys, {index});
  UniformityResult r;
  std::vector<double> count(k_a7_cells * k_a7_cells, 0.0);
  for (std::uint32_t key = 0; key < k_a7_uniform_keys; ++key) {
    const double x = v[std::size_t{key} * d + a], y = v[std::size_t{key} * d + b];
    if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0)) return r;
    r.same += x == v[a] && y == v[b];
    r.same_slab += static_cast<std::uint32_t>(x * slabs) == static_cast<std::uint32_t>(y * slabs);
    ++count[static_cast<std::size_t>(x * k_a7_cells) * k_a7_cells +
            static_cast<std::size_t>(y * k_a7_cells)];
  }
  const double expected =
      static_cast<double>(k_a7_uniform_keys) / static_cast<double>(count.size());
  double chi2 = 0.0;
  for (double c : count) chi2 += (c - expected) * (c - expected) / expected;
  r.p_value = chi_square_upper_tail(chi2, static_cast<double>(count.size() - 1));
  return r;
}

/// The verdict of point_uniformity at the three grading seeds, with `explain` naming the bug
/// from the first seed's counts when it fails.
template <class S, class Explain>
TaskResult check_uniformity(S& subject, A7PointSet kind, std::uint32_t n, unsigned d,
                            std::uint32_t index, unsigned a, unsigned b, std::uint32_t slabs,
                            Explain&& explain) {
  UniformityResult first;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    const UniformityResult r = point_uniformity(subject, kind, n, d, index, a, b, seed, slabs);
    if (seed == k_grading_seeds[0]) first = r;
    return r.p_value;
  });
  if (v.passed()) return {true, v.describe()};
  return {false, fmt::format("point {} of {} in dimensions {}, {} over {} keys is not uniform on "
                             "[0,1)^2: {}\n{}",
                             index, n, a, b, k_a7_uniform_keys, v.describe(), explain(first))};
}

inline std::string diagnose_unscrambled(const UniformityResult& r) {
  if (r.same > k_a7_uniform_keys / 2)
    return diagnosis(fmt::format(
        "an unscrambled point set claimed unbiased: the point is the same at {} of {} keys; "
        "a deterministic point is not uniform, so an estimate from the set is biased. Let the "
        "key choose random digit permutations",
        r.same, k_a7_uniform_keys));
  return diagnosis(
      "each point, taken alone, must be uniform over the keys: permute every digit "
      "position the set uses, and fill below them with a uniform number");
}

/// a7.1: point 5 of the k x k jittered set, uniform in dimensions 0 and 1.
template <class S>
TaskResult check_jittered_uniform(S& subject, std::uint32_t k = k_a7_grid) {
  return check_uniformity(subject, A7PointSet::jittered, k * k, 2, 5, 0, 1, 1,
                          [](const UniformityResult& r) {
                            if (r.same > k_a7_uniform_keys / 2)
                              return diagnosis(
                                  "the point does not depend on the key: draw the "
                                  "jitter and the cells' order from it");
                            return diagnosis(
                                "the cell a point takes must be uniform over the "
                                "keys (a random order of the cells), and its place "
                                "in the cell uniform (a random jitter u in [0, 1))");
                          });
}

/// a7.2: point 7 of the Latin hypercube set, uniform in dimensions 0 and d - 1 jointly.
template <class S>
TaskResult check_latin_uniform(S& subject, std::uint32_t n = k_a7_latin_n,
                               unsigned d = k_a7_latin_dims) {
  return check_uniformity(
      subject, A7PointSet::latin_hypercube, n, d, 7, 0, d - 1, n,
      [n, d](const UniformityResult& r) {
        // independent permutations put both in one slab at 1/n of the keys
        if (r.same_slab > k_a7_uniform_keys / 2)
          return diagnosis(fmt::format(
              "one permutation reused for every dimension: at {} of {} keys the point lies in "
              "the same slab of dimensions 0 and {}, so the points sit on the diagonal; give each "
              "dimension a permutation of its own (key it by j)",
              r.same_slab, k_a7_uniform_keys, d - 1));
        (void)n;
        return diagnosis(
            "each dimension's slab must be uniform over the keys, independently of "
            "the other dimensions'");
      });
}

/// a7.4: point 5 of the scrambled Halton set of 72, uniform in dimensions 0 and 1.
template <class S>
TaskResult check_halton_uniform(S& subject) {
  return check_uniformity(subject, A7PointSet::halton, k_a7_halton_n, 2, 5, 0, 1, 1,
                          [](const UniformityResult& r) { return diagnose_unscrambled(r); });
}

// ---------------------------------------------------------------- a7.1's rate

/// The smooth integrand of the rate test, f(x, y) = exp(x) cos(y) (its gradient never vanishes).
inline double a7_smooth(double x, double y) { return std::exp(x) * std::cos(y); }

/// The sample variance, over k_a7_rate_keys keys from `key0`, of the jittered estimate
/// (1/n) sum f(x_i) at n = k^2.
template <class S>
double jittered_estimate_variance(S& subject, std::uint32_t k, std::uint64_t key0) {
  const std::uint32_t n = k * k;
  const std::vector<double> v =
      subject.a7_points(A7PointSet::jittered, n, 2, key0, k_a7_rate_keys, a7_indices(n));
  double sum = 0.0, sum2 = 0.0;
  for (std::uint32_t r = 0; r < k_a7_rate_keys; ++r) {
    double estimate = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::size_t at = (std::size_t{r} * n + i) * 2;
      estimate += a7_smooth(v[at], v[at + 1]);
    }
    estimate /= n;
    sum += estimate;
    sum2 += estimate * estimate;
  }
  const double mean = sum / k_a7_rate_keys;
  return (sum2 - k_a7_rate_keys * mean * mean) / (k_a7_rate_keys - 1);
}

/// Jittered: Var = (1/n^2) sum_k sigma_k^2 with sigma_k^2 ~ |grad f|^2 / (12 k^2) in a cell of
/// side 1/k, so Var ~ c / n^2: from n = 16 to n = 256 it falls 256 times; independent points
/// (and one jitter shared by every cell, a randomly shifted grid) 16 times. Graded: the fall is
/// more than 64 (a slope in n steeper than -3/2). The p-value is that of the observed ratio T
/// under a true ratio of 64: log T is normal with variance 2 * 2/(R - 1) (two sample variances
/// of near-normal estimates, R keys each), so p = Phi((log T - log 64) / sqrt(4 / (R - 1))).
/// Measured over seeds 1-100 (diagnosis_test's A7Measure): log T = 5.53 (T = 253) with sd 0.112
/// (the model: 0.100), 12 sd above the limit; one jitter shared by every cell, log T = 2.78
/// (T = 16.1), 14 sd below it.
/// The fall graded: a ratio of the two variances consistent with less than this fails.
inline constexpr double k_a7_rate_limit = 64.0;
struct RateResult {
  double p_value = 0.0;
  double ratio = 0.0;
};
template <class S>
RateResult jittered_rate(S& subject, std::uint64_t seed) {
  const double coarse = jittered_estimate_variance(subject, 4, a7_first_key(seed));
  const double fine = jittered_estimate_variance(subject, 16, a7_first_key(seed) + (1u << 20));
  RateResult r;
  r.ratio = coarse / fine;
  if (!(r.ratio > 0.0) || !std::isfinite(r.ratio)) return r;
  const double z =
      (std::log(r.ratio) - std::log(k_a7_rate_limit)) / std::sqrt(4.0 / (k_a7_rate_keys - 1));
  r.p_value = 0.5 * std::erfc(-z / std::sqrt(2.0));
  return r;
}

template <class S>
TaskResult check_jittered_rate(S& subject) {
  double first_ratio = 0.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    const RateResult r = jittered_rate(subject, seed);
    if (seed == k_grading_seeds[0]) first_ratio = r.ratio;
    return r.p_value;
  });
  if (v.passed()) return {true, v.describe()};
  return {false,
          fmt::format("the variance of the estimate of exp(x) cos(y) falls {:.3g} times from "
                      "n = 16 to n = 256 (expected about 256, graded above {}): {}\n{}",
                      first_ratio, k_a7_rate_limit, v.describe(),
                      diagnosis("a variance that falls only as 1/n: does every stratum draw "
                                "its own jitter? One jitter shared by all cells is a "
                                "shifted grid, no better than random points here"))};
}

}  // namespace mcrt::testing::assignment
