// unit_circle_point against the maths library: (cos 2 pi u, sin 2 pi u) in every octant.

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "sampling/unit_circle.hpp"

using namespace mcrt;

namespace {

// std::cos(2 pi u) itself carries the rounding of 2 pi u (up to 2 pi * 2^-53 = 7e-16 at
// u near 1), and the series adds a few ulp: 2e-15 allows both and nothing else. A wrong
// coefficient, sign or octant would be off by far more (the smallest term, x^15/15!, is 3e-14).
constexpr double k_tolerance = 2e-15;

void expect_on_circle_at(double u) {
  const Vec2 p = unit_circle_point(u);
  EXPECT_NEAR(p.x, std::cos(k_two_pi * u), k_tolerance) << "u = " << u;
  EXPECT_NEAR(p.y, std::sin(k_two_pi * u), k_tolerance) << "u = " << u;
}

TEST(UnitCircleTest, MatchesTheMathsLibraryEverywhere) {
  Rng rng(21, 0);
  for (int i = 0; i < 20000; ++i) expect_on_circle_at(rng.uniform());
  // The octant boundaries, exactly and one step either side of them.
  for (int k = 0; k < 8; ++k) {
    const double u = k / 8.0;
    expect_on_circle_at(u);
    expect_on_circle_at(std::nextafter(u, 1.0));
    if (k > 0) expect_on_circle_at(std::nextafter(u, 0.0));
  }
  expect_on_circle_at(std::nextafter(1.0, 0.0));
}

TEST(UnitCircleTest, QuarterTurnsAreExact) {
  EXPECT_EQ(unit_circle_point(0.0), Vec2(1.0, 0.0));
  EXPECT_EQ(unit_circle_point(0.25), Vec2(0.0, 1.0));
  EXPECT_EQ(unit_circle_point(0.5), Vec2(-1.0, 0.0));
  EXPECT_EQ(unit_circle_point(0.75), Vec2(0.0, -1.0));
}

}  // namespace
