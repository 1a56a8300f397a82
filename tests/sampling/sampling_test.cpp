// Samplers on fixed inputs: the points lie in their domains and the mappings are the ones
// their pdfs describe. (Their distributions are checked with chi-square tests in
// tests/sampling/sampling_checks.cpp.)

#include <gtest/gtest.h>

#include "sampling/sampling.hpp"

using namespace mcrt;

namespace {

constexpr double k_tol = 1e-12;

TEST(SamplingTest, SquareMapsTheCornersAndCentre) {
  EXPECT_EQ(sample_uniform_square({0, 0}), Vec2(-1, -1));
  EXPECT_EQ(sample_uniform_square({0.5, 0.5}), Vec2(0, 0));
  EXPECT_DOUBLE_EQ(uniform_square_pdf() * 4.0, 1.0);  // pdf times area
}

TEST(SamplingTest, DiskRadiusIsTheSquareRootOfU) {
  for (double u0 : {0.0, 0.09, 0.25, 0.64, 0.999})
    for (double u1 : {0.0, 0.3, 0.77}) {
      const Vec2 p = sample_uniform_disk({u0, u1});
      EXPECT_NEAR(glm::length(p), std::sqrt(u0), k_tol);
    }
  EXPECT_DOUBLE_EQ(uniform_disk_pdf() * k_pi, 1.0);
}

TEST(SamplingTest, UniformHemisphereHasCosThetaEqualToU0) {
  for (double u0 : {0.0, 0.2, 0.5, 0.999})
    for (double u1 : {0.0, 0.4, 0.9}) {
      const Vec3 w = sample_uniform_hemisphere({u0, u1});
      EXPECT_NEAR(glm::length(w), 1.0, k_tol);
      EXPECT_NEAR(w.z, u0, k_tol);
      EXPECT_GE(w.z, 0.0);
    }
  EXPECT_DOUBLE_EQ(uniform_hemisphere_pdf() * k_two_pi, 1.0);
}

TEST(SamplingTest, CosineHemisphereIsTheLiftedDisk) {
  for (double u0 : {0.0, 0.2, 0.5, 0.999})
    for (double u1 : {0.0, 0.4, 0.9}) {
      const Vec3 w = sample_cosine_hemisphere({u0, u1});
      EXPECT_NEAR(glm::length(w), 1.0, k_tol);
      EXPECT_NEAR(w.z, std::sqrt(1.0 - u0), 1e-9);  // cos^2 theta = 1 - r^2 = 1 - u0
      EXPECT_NEAR(cosine_hemisphere_pdf(w.z), w.z / k_pi, k_tol);
    }
}

TEST(FrameTest, IsOrthonormalAndKeepsTheNormal) {
  for (const Vec3 n : {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0),
                       glm::normalize(Vec3(0.3, -0.8, 0.1)), glm::normalize(Vec3(-1e-9, 0, -1))}) {
    const Frame frame(n);
    EXPECT_NEAR(glm::dot(frame.tangent, frame.bitangent), 0.0, k_tol);
    EXPECT_NEAR(glm::dot(frame.tangent, n), 0.0, k_tol);
    EXPECT_NEAR(glm::dot(frame.bitangent, n), 0.0, k_tol);
    EXPECT_NEAR(glm::length(frame.tangent), 1.0, k_tol);
    EXPECT_NEAR(glm::length(frame.bitangent), 1.0, k_tol);
    const Vec3 w = frame.to_world({0.3, 0.4, std::sqrt(0.75)});
    EXPECT_NEAR(glm::dot(w, n), std::sqrt(0.75), k_tol);
  }
}

}  // namespace
