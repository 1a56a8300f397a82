// Assignment a2, sampling directions: the public tests (CTest label a2). Each sampler is graded
// by the chi-square test against its pdf and by the pdf integrating to 1 (a2_checks.hpp).

#include <gtest/gtest.h>

#include <cmath>

#include "assignments/a2/a2_checks.hpp"
#include "sampling/hemisphere.hpp"
#include "sampling/plane.hpp"
#include "sampling/sphere.hpp"

namespace mcrt::testing::assignment {
namespace {

double uniform_hemisphere_density(const Vec3&) { return uniform_hemisphere_pdf(); }
double cosine_hemisphere_density(const Vec3& w) { return cosine_hemisphere_pdf(w.z); }
double uniform_sphere_density(const Vec3&) { return uniform_sphere_pdf(); }
double uniform_disk_density(const Vec2&) { return uniform_disk_pdf(); }

TEST(A2, Task1UniformHemisphereFollowsItsPdf) {
  const TaskResult r = check_sampler(sample_uniform_hemisphere, uniform_hemisphere_density,
                                     sampler_hemisphere_binning(), SamplerKind::uniform_hemisphere,
                                     "a2_uniform_hemisphere");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task1UniformHemispherePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(uniform_hemisphere_density, sampler_hemisphere_binning(), "uniform_hemisphere_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task2CosineHemisphereFollowsItsPdf) {
  const TaskResult r = check_sampler(sample_cosine_hemisphere, cosine_hemisphere_density,
                                     sampler_hemisphere_binning(), SamplerKind::cosine_hemisphere,
                                     "a2_cosine_hemisphere");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task2CosineHemispherePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(cosine_hemisphere_density, sampler_hemisphere_binning(), "cosine_hemisphere_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task3UniformSphereFollowsItsPdf) {
  const TaskResult r = check_sampler(sample_uniform_sphere, uniform_sphere_density, sphere_binning(21, 21),
                                     SamplerKind::uniform_sphere, "a2_uniform_sphere");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task3UniformSpherePdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(uniform_sphere_density, sphere_binning(21, 21), "uniform_sphere_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task4UnitDiskFollowsItsPdf) {
  const TaskResult r = check_sampler(sample_uniform_disk, uniform_disk_density, sampler_disk_binning(),
                                     SamplerKind::unit_disk, "a2_unit_disk");
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A2, Task4UnitDiskPdfIntegratesToOne) {
  const TaskResult r = check_pdf_integral(uniform_disk_density, sampler_disk_binning(), "uniform_disk_pdf");
  EXPECT_TRUE(r.passed) << r.message;
}

// Directions are unit vectors: the chi-square bins by angle and would not see a length error.
TEST(A2, DirectionsAreUnitVectors) {
  for (double u0 : {0.0, 0.3, 0.999})
    for (double u1 : {0.0, 0.5, 0.999}) {
      EXPECT_NEAR(glm::length(sample_uniform_hemisphere({u0, u1})), 1.0, 1e-12) << "a2.1 at u = " << u0 << ", " << u1;
      EXPECT_NEAR(glm::length(sample_cosine_hemisphere({u0, u1})), 1.0, 1e-12) << "a2.2 at u = " << u0 << ", " << u1;
      EXPECT_NEAR(glm::length(sample_uniform_sphere({u0, u1})), 1.0, 1e-12) << "a2.3 at u = " << u0 << ", " << u1;
    }
}

}  // namespace
}  // namespace mcrt::testing::assignment
