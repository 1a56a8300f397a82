#pragma once
// Known-wrong point sets and radical inverses of assignment a7, each the solution of
// sampling/point_sets.hpp or sampling/radical_inverse.hpp but for what it names: the grading
// procedures of tests/assignments/a7/a7_checks.hpp must reject each with its diagnosis
// (tests/assignments/diagnosis_test.cpp). Withheld from every kit (scripts/make-assignment,
// WITHHELD_FILES): each shows a task's solution.

#include <cmath>
#include <cstdint>

#include "sampling/permutation.hpp"
#include "sampling/point_random.hpp"
#include "sampling/point_sets.hpp"
#include "sampling/radical_inverse.hpp"

namespace mcrt::testing {

/// Wrong: the jitter centred on the cell, (c + u - 1/2) / k (wrapped into [0, 1)): half of each
/// point's range lies in the next stratum, so some strata get two points and others none.
struct JitterOutsideItsStratum {
  std::uint32_t n;
  unsigned dimensions;
  std::uint64_t key;
  double operator()(std::uint32_t i, unsigned j) const {
    const std::uint32_t columns = JitteredPoints::grid_columns(n), rows = n / columns;
    const std::uint32_t cell = permutation_element(i, n, hash_bits(key, ~std::uint64_t{0}, j / 2));
    const double jitter = hash_uniform(key, i, j) - 0.5;
    const double x =
        j % 2 == 0 ? (cell % columns + jitter) / columns : (cell / columns + jitter) / rows;
    return x < 0.0 ? x + 1.0 : x;
  }
};

/// Wrong: one jitter for every cell (keyed by the set, not by the point): still one point per
/// stratum and each point uniform, but the set is a randomly shifted grid, whose error on a
/// smooth integrand falls as n^-1/2 only.
struct JitterSharedByEveryStratum {
  std::uint32_t n;
  unsigned dimensions;
  std::uint64_t key;
  double operator()(std::uint32_t i, unsigned j) const {
    const std::uint32_t columns = JitteredPoints::grid_columns(n), rows = n / columns;
    const std::uint32_t cell = permutation_element(i, n, hash_bits(key, ~std::uint64_t{0}, j / 2));
    const double jitter = hash_uniform(key, 0, j);
    return j % 2 == 0 ? (cell % columns + jitter) / columns : (cell / columns + jitter) / rows;
  }
};

/// Wrong: one permutation of the slabs reused for every dimension: each dimension alone is
/// still one point per slab, but point i lies in slab pi(i) of every dimension, on the diagonal.
struct LatinHypercubeOnePermutation {
  std::uint32_t n;
  std::uint64_t key;
  double operator()(std::uint32_t i, unsigned j) const {
    const std::uint32_t slab = permutation_element(i, n, hash_bits(key, ~std::uint64_t{0}, 0));
    return (slab + hash_uniform(key, i, j)) / n;
  }
};

/// Wrong: the plain Halton set, phi_{p_j}(i), claimed unbiased: stratified, but the same
/// points for every key, so no point is uniform and an estimate from them is biased.
struct UnscrambledHalton {
  std::uint32_t n;
  std::uint64_t key;
  double operator()(std::uint32_t i, unsigned j) const {
    return radical_inverse(i, HaltonPoints::prime(j));
  }
};

/// Wrong: the digits of i read in their own order after the point, i / b^K (K digits), instead
/// of mirrored: phi(1) = phi(b) = 1/b.
inline double radical_inverse_digits_in_order(std::uint32_t i, std::uint32_t base) {
  double scale = 1.0;
  for (std::uint32_t rest = i; rest != 0; rest /= base) scale *= base;
  return i / scale;
}

}  // namespace mcrt::testing
