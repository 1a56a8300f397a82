// Compensated (Neumaier) summation, common/integration/compensated_sum.hpp: what a plain running
// sum loses, it keeps. The quadrature rules rely on it (their truncation error at 10^6 points
// is the size of a plain sum's round-off), but their tests cannot see a few ulps; these can.

#include <cstdint>

#include <gtest/gtest.h>

#include "integration/compensated_sum.hpp"

namespace {

using mcrt::CompensatedSum;

TEST(CompensatedSumTest, EmptySumIsZeroAndOneTermIsItself) {
  EXPECT_EQ(CompensatedSum().value(), 0.0);
  CompensatedSum one;
  one.add(0.1);
  EXPECT_EQ(one.value(), 0.1);
}

// 1 + 10^6 terms of 1e-16: each term is below half an ulp of 1 (1.1e-16), so a plain running
// sum drops every one of them and returns exactly 1. The exact sum is 1 + 1e-10 (to 1e-26: the
// double nearest 1e-16 is off by 2e-33); the compensation collects the lost terms, so the result
// is that sum rounded once, within one ulp of 1 (2.2e-16) of 1 + 1e-10. A plain sum is 1e-10 off.
TEST(CompensatedSumTest, KeepsTermsBelowHalfAnUlpOfTheSum) {
  CompensatedSum sum;
  double plain = 1.0;
  sum.add(1.0);
  for (int i = 0; i < 1'000'000; ++i) {
    sum.add(1e-16);
    plain += 1e-16;
  }
  EXPECT_EQ(plain, 1.0);  // what the compensation is for
  EXPECT_NEAR(sum.value(), 1.0 + 1e-10, 2.3e-16);
}

// Neumaier's case, where a term is larger than the running sum: 1 + 1e100 + 1 - 1e100 = 2.
// A plain sum (and Kahan's, which assumes the sum is the larger) gives 0.
TEST(CompensatedSumTest, KeepsSmallTermsAcrossALargerTermThatCancels) {
  CompensatedSum sum;
  for (double term : {1.0, 1e100, 1.0, -1e100}) sum.add(term);
  EXPECT_EQ(sum.value(), 2.0);
}

// Terms of every sign and size whose exact sum is known: +x and -x for many x cancel exactly,
// leaving the one odd term. Each pair's partial sums round, and the compensation must undo it.
TEST(CompensatedSumTest, PairsThatCancelLeaveTheOddTerm) {
  CompensatedSum sum;
  sum.add(0.75);
  double x = 1.0 / 3.0;
  for (int i = 0; i < 200; ++i, x *= 1.37) sum.add(x);
  x = 1.0 / 3.0;
  for (int i = 0; i < 200; ++i, x *= 1.37) sum.add(-x);
  EXPECT_EQ(sum.value(), 0.75);
}

}  // namespace
