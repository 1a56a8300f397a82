// Point sets (sampling/point_sets.hpp): each one's stratification checked exactly (Sobol' at
// 2^m before and after scrambling, jittered, Latin hypercube, Halton at powers of its bases),
// each randomised point uniform by a chi-square over many keys, each estimate unbiased by a
// z-test against a closed form; the plain Sobol' net, deterministic, is shown biased.

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/math.hpp"
#include "sampling/point_sets.hpp"
#include "stats/chi_square.hpp"

using namespace mcrt;
using mcrt::testing::CellCount;
using mcrt::testing::chi_square_test;

namespace {

// The cell of [0,1) of width 1/cells that holds x.
std::uint32_t cell_of(double x, std::uint32_t cells) {
  return static_cast<std::uint32_t>(std::floor(x * cells));
}

// Whether the n points hold exactly one point in each of the nx x ny cells of dims (a, b).
template <class Points>
bool one_per_box(const Points& points, std::uint32_t n, unsigned a, unsigned b, std::uint32_t nx,
                 std::uint32_t ny) {
  std::vector<int> count(std::size_t{nx} * ny, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double x = points(i, a);
    const double y = points(i, b);
    if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0)) return false;
    ++count[cell_of(y, ny) * nx + cell_of(x, nx)];
  }
  for (const int c : count)
    if (c != 1) return false;
  return true;
}

// Whether dimension j of the n points holds one point in each of the n slabs [k/n, (k+1)/n).
template <class Points>
bool one_per_slab(const Points& points, std::uint32_t n, unsigned j) {
  std::vector<int> count(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double x = points(i, j);
    if (!(x >= 0.0 && x < 1.0)) return false;
    ++count[cell_of(x, n)];
  }
  for (const int c : count)
    if (c != 1) return false;
  return true;
}

TEST(SobolTest, IsANetBeforeAndAfterScrambling) {
  for (const SobolScramble scramble :
       {SobolScramble::none, SobolScramble::xor_shift, SobolScramble::owen})
    for (std::uint64_t key : {1ull, 2ull, 99ull})
      for (unsigned m = 0; m <= 12; ++m) {
        const std::uint32_t n = 1u << m;
        const SobolPoints points{n, key, scramble};
        // Dimensions 0 and 1 are a (0,m,2)-net: every elementary box 2^-k x 2^-(m-k).
        for (unsigned k = 0; k <= m; ++k)
          ASSERT_TRUE(one_per_box(points, n, 0, 1, 1u << k, 1u << (m - k)))
              << "m = " << m << ", k = " << k << ", scramble " << static_cast<int>(scramble);
        // Every dimension alone is a (0,m,1)-net.
        for (unsigned j = 0; j < 16; ++j) ASSERT_TRUE(one_per_slab(points, n, j)) << "dim " << j;
      }
}

TEST(JitteredTest, OnePointPerStratumIn1DAnd2D) {
  for (std::uint32_t n : {1u, 2u, 7u, 16u, 32u, 100u, 1024u, 2048u, 1013u}) {
    EXPECT_TRUE(one_per_slab(JitteredPoints{n, 1, 5}, n, 0)) << n;
    const JitteredPoints points{n, 5, 5};
    const std::uint32_t columns = JitteredPoints::grid_columns(n);
    EXPECT_EQ(n % columns, 0u);
    EXPECT_TRUE(one_per_box(points, n, 0, 1, columns, n / columns)) << n;
    EXPECT_TRUE(one_per_box(points, n, 2, 3, columns, n / columns)) << n;
    EXPECT_TRUE(one_per_slab(points, n, 4)) << n;  // the odd dimension out: 1D strata
  }
  EXPECT_EQ(JitteredPoints::grid_columns(64), 8u);
  EXPECT_EQ(JitteredPoints::grid_columns(32), 4u);  // 4 x 8 cells
}

TEST(LatinHypercubeTest, OnePointPerSlabInEveryDimension) {
  for (std::uint32_t n : {1u, 2u, 3u, 7u, 16u, 100u, 1000u})
    for (unsigned j = 0; j < 8; ++j)
      EXPECT_TRUE(one_per_slab(LatinHypercubePoints{n, 11}, n, j)) << n << ", dim " << j;
}

TEST(HaltonTest, StratifiesEachDimensionAtPowersOfItsBase) {
  // n = p^k points of dimension j (base p) fill the p^k slabs of width p^-k once each.
  for (const auto& [j, n] : {std::pair{0u, 1024u}, {1u, 729u}, {2u, 625u}, {3u, 343u}})
    for (std::uint64_t key : {3ull, 4ull}) EXPECT_TRUE(one_per_slab(HaltonPoints{n, key}, n, j));
}

// Point i of a set, over many keys, must be uniform on [0,1)^2 (dimensions j and j + 1):
// the chi-square over a 32 x 32 grid of 40,000 keys (about 39 expected a cell). The grid is
// fine enough to see a fill that covers a third of a Halton digit's last interval.
template <class MakePoints>
double uniformity_p_value(MakePoints make, std::uint32_t i, unsigned j) {
  constexpr int k_cells = 32;
  constexpr int k_keys = 40000;
  std::vector<CellCount> cells(k_cells * k_cells);
  for (int c = 0; c < k_cells * k_cells; ++c)
    cells[c] = {c % k_cells, c / k_cells, 0.0, double(k_keys) / (k_cells * k_cells)};
  for (std::uint64_t key = 0; key < k_keys; ++key) {
    const auto points = make(key);
    cells[cell_of(points(i, j + 1), k_cells) * k_cells + cell_of(points(i, j), k_cells)].observed +=
        1;
  }
  return chi_square_test(std::move(cells), 0).p_value;
}

TEST(PointSetsTest, EachRandomisedPointIsUniform) {
  // 6 sets x 3 points x 2 dimension pairs = 36 tests; Sidak at a family-wise 1e-4 puts each
  // at about 2.8e-6. Fixed keys make the test deterministic; 1e-4 is its chance to have been
  // unlucky when the seeds were chosen.
  const double alpha = 1.0 - std::pow(1.0 - 1e-4, 1.0 / 36);
  constexpr std::uint32_t n = 48;  // not a power of two: the plain case must work too
  for (const std::uint32_t i : {0u, 7u, 47u})
    for (const unsigned j : {0u, 4u}) {
      EXPECT_GT(uniformity_p_value(
                    [](std::uint64_t k) {
                      return IndependentPoints{n, k};
                    },
                    i, j),
                alpha);
      EXPECT_GT(uniformity_p_value(
                    [](std::uint64_t k) {
                      return JitteredPoints{n, 6, k};
                    },
                    i, j),
                alpha);
      EXPECT_GT(uniformity_p_value(
                    [](std::uint64_t k) {
                      return LatinHypercubePoints{n, k};
                    },
                    i, j),
                alpha);
      EXPECT_GT(uniformity_p_value(
                    [](std::uint64_t k) {
                      return SobolPoints{n, k, SobolScramble::owen};
                    },
                    i, j),
                alpha);
      EXPECT_GT(uniformity_p_value(
                    [](std::uint64_t k) {
                      return SobolPoints{n, k, SobolScramble::xor_shift};
                    },
                    i, j),
                alpha);
      EXPECT_GT(uniformity_p_value(
                    [](std::uint64_t k) {
                      return HaltonPoints{n, k};
                    },
                    i, j),
                alpha);
    }
}

TEST(PointSetsTest, TheUnscrambledNetIsNotUniform) {
  // The check above must be able to fail: the plain net puts point 0 at the origin always.
  EXPECT_LT(uniformity_p_value(
                [](std::uint64_t) {
                  return SobolPoints{48, 0, SobolScramble::none};
                },
                0, 0),
            1e-12);
}

// The quarter disk's indicator on [0,1)^2, whose integral is pi/4: a discontinuous
// integrand, like chapter 02's.
double quarter_disk(double x, double y) { return x * x + y * y < 1.0 ? 1.0 : 0.0; }

// The z-score of the mean of R estimates (1/n) sum f(x_i), one per key, against pi/4.
template <class MakePoints>
double unbiasedness_z(MakePoints make, std::uint32_t n, int repetitions) {
  double sum = 0.0, sum_squares = 0.0;
  for (int r = 0; r < repetitions; ++r) {
    const auto points = make(static_cast<std::uint64_t>(r) + 1000);
    double estimate = 0.0;
    for (std::uint32_t i = 0; i < n; ++i) estimate += quarter_disk(points(i, 0), points(i, 1));
    estimate /= n;
    sum += estimate;
    sum_squares += estimate * estimate;
  }
  const double mean = sum / repetitions;
  const double variance = (sum_squares - repetitions * mean * mean) / (repetitions - 1);
  return (mean - k_pi / 4) / std::sqrt(variance / repetitions);
}

TEST(PointSetsTest, EveryRandomisedEstimateIsUnbiased) {
  // 6 z-tests of 4000 estimates each (the mean is normal to good accuracy); |z| < 4.6 is
  // two-sided 4.2e-6 each, a family-wise false-failure rate of 2.5e-5.
  constexpr double k_z = 4.6;
  constexpr std::uint32_t n = 64;
  constexpr int r = 4000;
  EXPECT_LT(std::abs(unbiasedness_z(
                [](std::uint64_t k) {
                  return IndependentPoints{n, k};
                },
                n, r)),
            k_z);
  EXPECT_LT(std::abs(unbiasedness_z(
                [](std::uint64_t k) {
                  return JitteredPoints{n, 2, k};
                },
                n, r)),
            k_z);
  EXPECT_LT(std::abs(unbiasedness_z(
                [](std::uint64_t k) {
                  return LatinHypercubePoints{n, k};
                },
                n, r)),
            k_z);
  EXPECT_LT(std::abs(unbiasedness_z(
                [](std::uint64_t k) {
                  return SobolPoints{n, k, SobolScramble::owen};
                },
                n, r)),
            k_z);
  EXPECT_LT(std::abs(unbiasedness_z(
                [](std::uint64_t k) {
                  return SobolPoints{n, k, SobolScramble::xor_shift};
                },
                n, r)),
            k_z);
  EXPECT_LT(std::abs(unbiasedness_z(
                [](std::uint64_t k) {
                  return HaltonPoints{n, k};
                },
                n, r)),
            k_z);
}

TEST(PointSetsTest, ThePlainNetIsBiased) {
  // Deterministic: every repetition gives the same estimate, which misses pi/4 (the 64-point
  // net counts 51 points inside, 0.796875 against 0.785398).
  const SobolPoints points{64, 0, SobolScramble::none};
  double estimate = 0.0;
  for (std::uint32_t i = 0; i < 64; ++i) estimate += quarter_disk(points(i, 0), points(i, 1));
  EXPECT_GT(std::abs(estimate / 64 - k_pi / 4), 1e-3);
}

}  // namespace
