// Hidden tests of a2: the samplers at the corners of [0,1)^2 stay finite and in their domains.

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/hemisphere.hpp"
#include "sampling/plane.hpp"
#include "sampling/sphere.hpp"

namespace mcrt {
namespace {

TEST(A2Hidden, CornersOfTheUnitSquare) {
  const double last = 1.0 - 0x1p-32;  // the largest uniform the generators return
  for (double u0 : {0.0, last})
    for (double u1 : {0.0, last}) {
      const Vec3 h = sample_uniform_hemisphere({u0, u1}), c = sample_cosine_hemisphere({u0, u1});
      EXPECT_GE(h.z, 0.0);
      EXPECT_GE(c.z, 0.0);
      EXPECT_TRUE(std::isfinite(h.x + h.y + h.z + c.x + c.y + c.z));
      EXPECT_LE(glm::length(sample_uniform_disk({u0, u1})), 1.0 + 1e-12);
      EXPECT_NEAR(glm::length(sample_uniform_sphere({u0, u1})), 1.0, 1e-12);
    }
}

}  // namespace
}  // namespace mcrt
