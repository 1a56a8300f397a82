// The hemisphere's samplers (sampling/hemisphere.hpp) on fixed inputs: unit directions above
// the surface, cos(theta) = u0 for the uniform one, the lifted disk for the cosine one, and the
// pdfs they promise. (Their distributions: tests/sampling/sampling_checks.cpp.)

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/hemisphere.hpp"

using namespace mcrt;

namespace {

constexpr double k_tol = 1e-12;  // exact up to rounding of values of order 1

TEST(HemisphereTest, UniformHemisphereHasCosThetaEqualToU0) {
  for (double u0 : {0.0, 0.2, 0.5, 0.999})
    for (double u1 : {0.0, 0.4, 0.9}) {
      const Vec3 w = sample_uniform_hemisphere({u0, u1});
      EXPECT_NEAR(glm::length(w), 1.0, k_tol);
      EXPECT_NEAR(w.z, u0, k_tol);
      EXPECT_GE(w.z, 0.0);
    }
  EXPECT_DOUBLE_EQ(uniform_hemisphere_pdf() * k_two_pi, 1.0);
}

TEST(HemisphereTest, CosineHemisphereIsTheLiftedDisk) {
  for (double u0 : {0.0, 0.2, 0.5, 0.999})
    for (double u1 : {0.0, 0.4, 0.9}) {
      const Vec3 w = sample_cosine_hemisphere({u0, u1});
      EXPECT_NEAR(glm::length(w), 1.0, k_tol);
      EXPECT_NEAR(w.z, std::sqrt(1.0 - u0), 1e-9);  // cos^2 theta = 1 - r^2 = 1 - u0
      EXPECT_NEAR(cosine_hemisphere_pdf(w.z), w.z / k_pi, k_tol);
    }
}

}  // namespace
