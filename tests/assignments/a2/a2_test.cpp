// Assignment a2, sampling directions: the public tests (CTest label a2). Each sampler is graded
// by the chi-square test against its pdf and by the pdf integrating to 1 (a2_checks.hpp). The
// samplers are reached through subject() only: in-process here, in the subject program when
// scripts/grade builds this file as a checker.

#include <gtest/gtest.h>

#include <cmath>

#include "assignments/a2/a2_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A2, Task1UniformHemisphereFollowsItsPdf) {
  const TaskResult r = check_sampler(samples_of<Vec3>(subject(), SamplerKind::uniform_hemisphere),
                                     pdf_of<Vec3>(subject(), SamplerKind::uniform_hemisphere),
                                     sampler_hemisphere_binning(), SamplerKind::uniform_hemisphere,
                                     "a2_uniform_hemisphere");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task1UniformHemispherePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(pdf_of<Vec3>(subject(), SamplerKind::uniform_hemisphere),
                                          sampler_hemisphere_binning(), "uniform_hemisphere_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task2CosineHemisphereFollowsItsPdf) {
  const TaskResult r = check_sampler(samples_of<Vec3>(subject(), SamplerKind::cosine_hemisphere),
                                     pdf_of<Vec3>(subject(), SamplerKind::cosine_hemisphere),
                                     sampler_hemisphere_binning(), SamplerKind::cosine_hemisphere,
                                     "a2_cosine_hemisphere");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task2CosineHemispherePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(pdf_of<Vec3>(subject(), SamplerKind::cosine_hemisphere),
                                          sampler_hemisphere_binning(), "cosine_hemisphere_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task3UniformSphereFollowsItsPdf) {
  const TaskResult r =
      check_sampler(samples_of<Vec3>(subject(), SamplerKind::uniform_sphere),
                    pdf_of<Vec3>(subject(), SamplerKind::uniform_sphere), sphere_binning(21, 21),
                    SamplerKind::uniform_sphere, "a2_uniform_sphere");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task3UniformSpherePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(pdf_of<Vec3>(subject(), SamplerKind::uniform_sphere),
                                          sphere_binning(21, 21), "uniform_sphere_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task4UnitDiskFollowsItsPdf) {
  const TaskResult r =
      check_sampler(samples_of<Vec2>(subject(), SamplerKind::unit_disk),
                    pdf_of<Vec2>(subject(), SamplerKind::unit_disk), sampler_disk_binning(),
                    SamplerKind::unit_disk, "a2_unit_disk");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task4UnitDiskPdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(pdf_of<Vec2>(subject(), SamplerKind::unit_disk),
                                          sampler_disk_binning(), "uniform_disk_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task5UniformConeFollowsItsPdf) {
  const TaskResult r =
      check_sampler(samples_of<Vec3>(subject(), SamplerKind::uniform_cone),
                    pdf_of<Vec3>(subject(), SamplerKind::uniform_cone), sampler_cone_binning(),
                    SamplerKind::uniform_cone, "a2_uniform_cone");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task5UniformConePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(pdf_of<Vec3>(subject(), SamplerKind::uniform_cone),
                                          sampler_cone_binning(), "uniform_cone_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

// Outside the cone the sampler never goes, so its pdf is 0 there: the chi-square and the
// integral see the cone only and would miss a constant pdf that ignores cos(theta_max).
TEST(A2, Task5UniformConePdfIsZeroOutsideTheCone) {
  std::vector<Vec3> outside;
  for (double z : {k_a2_cone_cos_theta_max - 0.01, 0.5, 0.0, -0.7}) {
    const double s = std::sqrt(1.0 - z * z);
    outside.emplace_back(s * 0.6, s * 0.8, z);
  }
  const std::vector<double> p = subject().pdf_values(SamplerKind::uniform_cone, outside);
  for (std::size_t i = 0; i < outside.size(); ++i)
    EXPECT_EQ(p[i], 0.0) << "uniform_cone_pdf at cos(theta) = " << outside[i].z
                         << " (outside the cone of cos(theta_max) = " << k_a2_cone_cos_theta_max
                         << ") must be 0";
}

// Directions are unit vectors: the chi-square bins by angle and would not see a length error.
TEST(A2, DirectionsAreUnitVectors) {
  std::vector<Vec2> u;
  for (double u0 : {0.0, 0.3, 0.999})
    for (double u1 : {0.0, 0.5, 0.999}) u.emplace_back(u0, u1);
  const std::vector<Vec3> h = subject().samples(SamplerKind::uniform_hemisphere, u);
  const std::vector<Vec3> c = subject().samples(SamplerKind::cosine_hemisphere, u);
  const std::vector<Vec3> s = subject().samples(SamplerKind::uniform_sphere, u);
  const std::vector<Vec3> k = subject().samples(SamplerKind::uniform_cone, u);
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_NEAR(glm::length(h[i]), 1.0, 1e-12) << "a2.1 at u = " << u[i].x << ", " << u[i].y;
    EXPECT_NEAR(glm::length(c[i]), 1.0, 1e-12) << "a2.2 at u = " << u[i].x << ", " << u[i].y;
    EXPECT_NEAR(glm::length(s[i]), 1.0, 1e-12) << "a2.3 at u = " << u[i].x << ", " << u[i].y;
    EXPECT_NEAR(glm::length(k[i]), 1.0, 1e-12) << "a2.5 at u = " << u[i].x << ", " << u[i].y;
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
