// Random numbers by address (sampling/point_random.hpp): in [0,1), distinct for distinct
// addresses, and with the mean and variance of a uniform.

#include <cmath>
#include <cstdint>
#include <set>

#include <gtest/gtest.h>

#include "sampling/point_random.hpp"

using namespace mcrt;

namespace {

TEST(PointRandomTest, EveryPartOfTheAddressMatters) {
  std::set<std::uint64_t> words;
  for (std::uint64_t key = 0; key < 8; ++key)
    for (std::uint64_t a = 0; a < 8; ++a)
      for (std::uint64_t b = 0; b < 8; ++b) words.insert(hash_bits(key, a, b));
  EXPECT_EQ(words.size(), 512u);
  EXPECT_NE(hash_bits(0, 1, 2), hash_bits(0, 2, 1));  // the parts are not symmetric
}

TEST(PointRandomTest, HasAUniformsMeanAndVariance) {
  constexpr int n = 1 << 20;
  double sum = 0.0, sum_squares = 0.0;
  for (int i = 0; i < n; ++i) {
    const double u = hash_uniform(42, static_cast<std::uint64_t>(i), 3);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum_squares += u * u;
  }
  // The mean of 2^20 uniforms has standard error sqrt(1/12 / 2^20) = 2.8e-4; 5 of those is a
  // two-sided 5.7e-7. The variance estimate's standard error is sqrt(1/180 / 2^20) = 7.3e-5.
  EXPECT_NEAR(sum / n, 0.5, 5 * 2.8e-4);
  EXPECT_NEAR(sum_squares / n - (sum / n) * (sum / n), 1.0 / 12, 5 * 7.3e-5);
}

}  // namespace
