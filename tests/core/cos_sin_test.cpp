// cos_sin_two_pi against cosl and sinl in long double (64-bit mantissa, so the reference's own
// error, about 1e-19, is far below the bound checked): every quarter turn, both ends of each
// reduction interval, and a dense grid.

#include <cmath>

#include <gtest/gtest.h>

#include "core/cos_sin.hpp"

using namespace mcrt;

namespace {

// The bound the header documents: Taylor truncation < 5e-17, plus a few roundings of values
// at most 1 (each under 1.1e-16 absolute) in the argument x and the last Horner steps.
constexpr double k_bound = 3e-16;

long double exact_angle(double u) {
  return 2.0L * 3.14159265358979323846264338327950288L * static_cast<long double>(u);
}

void expect_close(double u) {
  const Vec2 cs = cos_sin_two_pi(u);
  const long double angle = exact_angle(u);
  EXPECT_LE(std::abs(static_cast<long double>(cs.x) - std::cos(angle)), k_bound) << "u = " << u;
  EXPECT_LE(std::abs(static_cast<long double>(cs.y) - std::sin(angle)), k_bound) << "u = " << u;
}

TEST(CosSinTest, QuarterTurnsAreExact) {
  EXPECT_EQ(cos_sin_two_pi(0.0), Vec2(1.0, 0.0));
  EXPECT_EQ(cos_sin_two_pi(0.25), Vec2(0.0, 1.0));
  EXPECT_EQ(cos_sin_two_pi(0.5), Vec2(-1.0, 0.0));
  EXPECT_EQ(cos_sin_two_pi(0.75), Vec2(0.0, -1.0));
  EXPECT_EQ(cos_sin_two_pi(1.0), Vec2(1.0, 0.0));
}

TEST(CosSinTest, WithinTheBoundAtTheEndsOfEveryReductionInterval) {
  // x = +-pi/4, where the series' truncation error is largest, and where q changes.
  for (double centre : {0.125, 0.375, 0.625, 0.875})
    for (double u : {std::nextafter(centre, 0.0), centre, std::nextafter(centre, 1.0)})
      expect_close(u);
  expect_close(std::nextafter(1.0, 0.0));  // the largest uniform the generator gives is 1 - 2^-32
  expect_close(1.0 - 0x1p-32);
  expect_close(0x1p-32);
}

TEST(CosSinTest, WithinTheBoundOnADenseGrid) {
  constexpr int k_points = 1 << 16;
  double worst = 0.0;
  for (int i = 0; i <= k_points; ++i) {
    const double u = static_cast<double>(i) / k_points + 0x1p-40 * (i % 7);
    const Vec2 cs = cos_sin_two_pi(u);
    const long double angle = exact_angle(u);
    worst = std::max({worst, static_cast<double>(std::abs(cs.x - std::cos(angle))),
                      static_cast<double>(std::abs(cs.y - std::sin(angle)))});
  }
  EXPECT_LE(worst, k_bound);
}

TEST(CosSinTest, PointsLieOnTheUnitCircle) {
  for (int i = 0; i < 1000; ++i) {
    const Vec2 cs = cos_sin_two_pi(i / 1000.0);
    // Each coordinate is within 3e-16, so |p|^2 is within 2 * 3e-16 + round-off of 1.
    EXPECT_NEAR(cs.x * cs.x + cs.y * cs.y, 1.0, 1e-15);
  }
}

}  // namespace
