// The local frame around a normal (sampling/frame.hpp): orthonormal for every normal, the
// axis-aligned and nearly axis-aligned ones included, and it keeps the normal as its z.

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/frame.hpp"

using namespace mcrt;

namespace {

constexpr double k_tol = 1e-12;  // exact up to rounding of values of order 1

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
