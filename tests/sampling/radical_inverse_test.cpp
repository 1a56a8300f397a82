// The radical inverse (sampling/radical_inverse.hpp): van der Corput's first values exactly,
// the first b^m values filling the b^m intervals of width b^-m once each, and the digit
// recurrence phi_b(b i + d) = (d + phi_b(i)) / b that defines it; a radical inverse with its
// digits in their own order (tests/sampling/point_sets_known_bugs_a7.hpp) fails the last two.

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "sampling/point_sets_known_bugs_a7.hpp"
#include "sampling/radical_inverse.hpp"

namespace {

using Phi = double (*)(std::uint32_t, std::uint32_t);

/// Whether phi's first b^m values hold one in each interval [k b^-m, (k+1) b^-m).
bool fills_every_interval(Phi phi, std::uint32_t b, unsigned m) {
  std::uint32_t n = 1;
  for (unsigned k = 0; k < m; ++k) n *= b;
  std::vector<int> count(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const double x = phi(i, b);
    if (!(x >= 0.0 && x < 1.0)) return false;
    // x is k / n to within a rounding: the nearest k (the interval's left end)
    ++count[static_cast<std::size_t>(std::lround(x * n))];
  }
  for (int c : count)
    if (c != 1) return false;
  return true;
}

/// Whether phi(b i + d) = (d + phi(i)) / b for every b i + d < limit (to 1e-14: a few
/// roundings of 1.1e-16, while a wrong digit moves a value by at least 1/limit).
bool follows_the_recurrence(Phi phi, std::uint32_t b, std::uint32_t limit) {
  for (std::uint32_t i = 0; b * i < limit; ++i)
    for (std::uint32_t d = 0; d < b && b * i + d < limit; ++d)
      if (!(std::abs(phi(b * i + d, b) - (d + phi(i, b)) / b) <= 1e-14)) return false;
  return phi(0, b) == 0.0;
}

TEST(RadicalInverse, VanDerCorputsFirstValues) {
  const double expected[] = {0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875};
  for (std::uint32_t i = 0; i < 8; ++i) EXPECT_EQ(mcrt::radical_inverse(i, 2), expected[i]) << i;
  EXPECT_EQ(mcrt::radical_inverse(5, 3), 7.0 / 9.0);  // 5 = 12 in base 3: 0.21 = 2/3 + 1/9
}

TEST(RadicalInverse, FirstBToTheMValuesFillEveryInterval) {
  for (std::uint32_t b : {2u, 3u, 5u, 7u, 131u})
    EXPECT_TRUE(fills_every_interval(&mcrt::radical_inverse, b, b == 131 ? 2 : 4)) << b;
  EXPECT_FALSE(fills_every_interval(&mcrt::testing::radical_inverse_digits_in_order, 2, 4));
}

TEST(RadicalInverse, AppendingADigitDividesByTheBase) {
  for (std::uint32_t b : {2u, 3u, 5u, 13u})
    EXPECT_TRUE(follows_the_recurrence(&mcrt::radical_inverse, b, 5000)) << b;
  EXPECT_FALSE(follows_the_recurrence(&mcrt::testing::radical_inverse_digits_in_order, 3, 5000));
}

TEST(RadicalInverse, LargestIndexStaysBelowOne) {
  // 2^32 - 1 in base 2: 32 ones mirrored, 1 - 2^-32 exactly
  EXPECT_EQ(mcrt::radical_inverse(0xffffffffu, 2), 1.0 - 0x1p-32);
  EXPECT_LT(mcrt::radical_inverse(0xffffffffu, 131), 1.0);
}

}  // namespace
