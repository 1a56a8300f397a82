#pragma once
/// Point sets: the i-th point of a set of n in [0,1)^d, randomised by a key.
///
/// Every set here is randomised so that each of its points, taken alone, is uniform on
/// [0,1)^d: an estimate (1/n) sum f(x_i) then has expectation exactly the integral of f,
/// whatever the set does to its variance. They differ in how the n points sit together:
///
///   IndependentPoints     no relation: Var = sigma^2 / n, the error falls as n^-1/2
///   JitteredPoints        one point in each cell of a grid (1D: n strata; 2D: a near-square
///                         grid per pair of dimensions, the pairs padded by permuting cells)
///   LatinHypercubePoints  one point in each of the n slabs of every single dimension
///   SobolPoints           a (t,m,s)-net at n = 2^m, Owen-scrambled or shifted by a random xor
///   HaltonPoints          the radical inverse in base p_j, its digits randomly permuted
///
/// Each is a small value type with the same call: points(i, j) is coordinate j of point i.
/// No point set allocates, and each point is a pure function of (key, n, i, j), so a pixel's
/// samples do not depend on the thread that draws them.

#include <cstdint>
#include <stdexcept>

#include "sampling/owen_scramble.hpp"
#include "sampling/permutation.hpp"
#include "sampling/point_random.hpp"
#include "sampling/sobol_matrices.hpp"

namespace mcrt {

/// Independent uniform points: each coordinate its own hash.
struct IndependentPoints {
  std::uint32_t n;
  std::uint64_t key;
  double operator()(std::uint32_t i, unsigned j) const { return hash_uniform(key, i, j); }
};

/// Jittered (stratified) points. With one dimension, point i lies in [i/n, (i+1)/n). With
/// more, dimensions (0,1), (2,3), ... each form a grid of nx x ny = n cells (nx the largest
/// divisor of n at most sqrt(n)), point i in one cell of each; a last odd dimension is
/// stratified in 1D. Each pair visits its cells in its own random order (padding), so the
/// pairs do not correlate. Stratified estimate: Var = (1/n^2) sum_k sigma_k^2, the
/// within-cell variances, never more than independent points' sigma^2 / n.
struct JitteredPoints {
  std::uint32_t n;
  unsigned dimensions;
  std::uint64_t key;

  /// Columns of the 2D grid: the largest divisor of n not above sqrt(n).
  static std::uint32_t grid_columns(std::uint32_t n) {
    std::uint32_t columns = 1;
    for (std::uint32_t c = 1; std::uint64_t{c} * c <= n; ++c)
      if (n % c == 0) columns = c;
    return columns;
  }

  double operator()(std::uint32_t i, unsigned j) const {
    // ASSIGNMENT a7.1 BEGIN stub: (void)i; (void)j; NOT_IMPLEMENTED(JitteredPoints);
    const double jitter = hash_uniform(key, i, j);
    const unsigned pair = j / 2;
    const std::uint32_t cell = permutation_element(i, n, hash_bits(key, ~std::uint64_t{0}, pair));
    if (dimensions == 1 || (j == dimensions - 1 && j % 2 == 0))
      return (cell + jitter) / n;  // 1D strata
    const std::uint32_t columns = grid_columns(n);
    const std::uint32_t rows = n / columns;
    return j % 2 == 0 ? (cell % columns + jitter) / columns : (cell / columns + jitter) / rows;
    // ASSIGNMENT a7.1 END
  }
};

/// Latin hypercube (n-rooks) points: in every dimension j, the n points fill the n slabs
/// [k/n, (k+1)/n) once each, in a random order of their own (a permutation per dimension).
/// Var = sigma^2/n - (1/n) sum_j sigma_j^2 + o(1/n), sigma_j^2 the variance of f's additive
/// part in dimension j (Stein 1987): the one-dimensional parts are integrated away, and the
/// variance is never above sigma^2/(n-1) (Owen 1997).
struct LatinHypercubePoints {
  std::uint32_t n;
  std::uint64_t key;
  double operator()(std::uint32_t i, unsigned j) const {
    // ASSIGNMENT a7.2 BEGIN stub: (void)i; (void)j; NOT_IMPLEMENTED(LatinHypercubePoints);
    const std::uint32_t slab = permutation_element(i, n, hash_bits(key, ~std::uint64_t{0}, j));
    return (slab + hash_uniform(key, i, j)) / n;
    // ASSIGNMENT a7.2 END
  }
};

/// How a Sobol' set is randomised.
enum class SobolScramble {
  none,       ///< the plain net: deterministic, so an estimate from it is biased in general
  xor_shift,  ///< a random digital shift (xor) per dimension: uniform points, the net kept
  owen,       ///< Owen's nested scramble: uniform points, the net kept, and Var = o(1/n)
};

/// Sobol' points, dimension j < k_sobol_max_dimensions. At n = 2^m they are a (t,m,s)-net
/// (dimensions 0 and 1: t = 0, one point per elementary box of area 2^-m). Owen-scrambled,
/// a smooth integrand's RMS error falls as n^-3/2 (times log factors) at n = 2^m.
struct SobolPoints {
  std::uint32_t n;
  std::uint64_t key;
  SobolScramble scramble = SobolScramble::owen;

  double operator()(std::uint32_t i, unsigned j) const {
    std::uint32_t bits = sobol_bits(i, j);
    const auto seed = static_cast<std::uint32_t>(hash_bits(key, ~std::uint64_t{0}, j));
    if (scramble == SobolScramble::xor_shift) bits ^= seed;
    if (scramble == SobolScramble::owen) bits = owen_scramble(bits, seed);
    // The 32 bits are the top of the binary fraction; below them, a uniform fill completes
    // a randomised point to a uniform double (without it, values sit on a 2^-32 grid).
    const double fill = scramble == SobolScramble::none ? 0.0 : hash_uniform(key, i, j);
    return (bits + fill) * 0x1p-32;
  }
};

/// Halton points: dimension j is the radical inverse of i in the j-th prime p_j, each digit
/// position k's digits mapped through a random permutation of {0, ..., p_j - 1} (random-
/// permutation scrambling, as in Faure and Tezuka 2002). The first K positions are permuted,
/// K the digits of n - 1 (all a point of the set can have; a zero digit is permuted too);
/// below p_j^-K an independent uniform fill stands for the further permuted zeros, so each
/// point is uniform on [0,1) while the first K digits keep the set's stratification.
struct HaltonPoints {
  std::uint32_t n;
  std::uint64_t key;

  static constexpr unsigned k_max_dimensions = 32;
  static constexpr std::uint32_t prime(unsigned j) {
    constexpr std::uint32_t primes[k_max_dimensions] = {2,  3,   5,   7,   11,  13,  17,  19,
                                                        23, 29,  31,  37,  41,  43,  47,  53,
                                                        59, 61,  67,  71,  73,  79,  83,  89,
                                                        97, 101, 103, 107, 109, 113, 127, 131};
    return primes[j];
  }

  double operator()(std::uint32_t i, unsigned j) const {
    if (j >= k_max_dimensions) throw std::out_of_range("HaltonPoints: too many dimensions");
    // ASSIGNMENT a7.4 BEGIN stub: (void)i; NOT_IMPLEMENTED(HaltonPoints);
    const std::uint32_t base = prime(j);
    const std::uint64_t dimension_key = hash_bits(key, ~std::uint64_t{0}, j);
    double width = 1.0;  // of the interval the digits so far have chosen: p^-k
    double value = 0.0;
    std::uint32_t digits = i;
    for (std::uint32_t rest = n - 1, k = 0; rest != 0; rest /= base, digits /= base, ++k) {
      width /= base;
      value += permutation_element(digits % base, base, dimension_key + k) * width;
    }
    value += hash_uniform(key, i, j) * width;           // uniform within the chosen interval
    return value < 1.0 ? value : 0x1.fffffffffffffp-1;  // the rounding of the sum
    // ASSIGNMENT a7.4 END
  }
};

}  // namespace mcrt
