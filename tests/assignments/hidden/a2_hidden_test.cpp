// Hidden tests of a2: the samplers at the corners of [0,1)^2 stay finite and in their domains.
// The corners travel as a request to the subject, which holds no hidden test.

#include <gtest/gtest.h>

#include <cmath>

#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A2Hidden, CornersOfTheUnitSquare) {
  const double last = 1.0 - 0x1p-32;  // the largest uniform the generators return
  std::vector<Vec2> u;
  for (double u0 : {0.0, last})
    for (double u1 : {0.0, last}) u.emplace_back(u0, u1);
  const std::vector<Vec3> h = subject().samples(SamplerKind::uniform_hemisphere, u);
  const std::vector<Vec3> c = subject().samples(SamplerKind::cosine_hemisphere, u);
  const std::vector<Vec3> d = subject().samples(SamplerKind::unit_disk, u);
  const std::vector<Vec3> s = subject().samples(SamplerKind::uniform_sphere, u);
  const std::vector<Vec3> k = subject().samples(SamplerKind::uniform_cone, u);
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_GE(h[i].z, 0.0);
    EXPECT_GE(c[i].z, 0.0);
    EXPECT_TRUE(std::isfinite(h[i].x + h[i].y + h[i].z + c[i].x + c[i].y + c[i].z));
    EXPECT_LE(glm::length(d[i]), 1.0 + 1e-12);
    EXPECT_NEAR(glm::length(s[i]), 1.0, 1e-12);
    // the cone's rim and axis: in the cone up to round-off, a unit vector
    EXPECT_GE(k[i].z, k_a2_cone_cos_theta_max - 1e-12);
    EXPECT_NEAR(glm::length(k[i]), 1.0, 1e-12);
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
