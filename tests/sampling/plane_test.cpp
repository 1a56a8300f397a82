// The square's and the disk's samplers (sampling/plane.hpp) on fixed inputs: corners and
// centre map where they must, the disk's radius is sqrt(u0), and each pdf times its area is 1.
// (Their distributions are checked with chi-square tests in tests/sampling/sampling_checks.cpp.)

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/plane.hpp"

using namespace mcrt;

namespace {

constexpr double k_tol = 1e-12;  // exact up to rounding of values of order 1

TEST(PlaneTest, SquareMapsTheCornersAndCentre) {
  EXPECT_EQ(sample_uniform_square({0, 0}), Vec2(-1, -1));
  EXPECT_EQ(sample_uniform_square({0.5, 0.5}), Vec2(0, 0));
  EXPECT_DOUBLE_EQ(uniform_square_pdf() * 4.0, 1.0);  // pdf times area
}

TEST(PlaneTest, DiskRadiusIsTheSquareRootOfU) {
  for (double u0 : {0.0, 0.09, 0.25, 0.64, 0.999})
    for (double u1 : {0.0, 0.3, 0.77}) {
      const Vec2 p = sample_uniform_disk({u0, u1});
      EXPECT_NEAR(glm::length(p), std::sqrt(u0), k_tol);
    }
  EXPECT_DOUBLE_EQ(uniform_disk_pdf() * k_pi, 1.0);
}

}  // namespace
