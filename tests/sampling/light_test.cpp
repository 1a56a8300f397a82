// Points on lights (sampling/light.hpp) on fixed seeds: quad and cap points lie on their
// surfaces with the normal and area pdf promised, the cone's points on the sphere's near side
// with p_A = p_w cos(theta_y) / r^2, and the change of measure p_w = p_A r^2 / |cos| both ways.
// (Their distributions are checked by chi-square in tests/render/next_event_estimation_checks.cpp.)

#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "render/next_event_estimation_procedures.hpp"
#include "sampling/light.hpp"

using namespace mcrt;

namespace {

TEST(LightPointsTest, QuadPointsLieOnTheQuadWithItsNormalAndPdf) {
  const Quad q = mcrt::testing::cornell_lamp();
  Rng rng(1, 0);
  for (int i = 0; i < 1000; ++i) {
    const LightPoint y = sample_quad(q.corner(), q.edge_u(), q.edge_v(), rng.uniform2());
    const Vec3 p = y.point - q.corner();
    EXPECT_NEAR(glm::dot(p, q.normal()), 0.0, 1e-9);
    EXPECT_GE(q.coordinate_a(p), -1e-12);
    EXPECT_LE(q.coordinate_a(p), 1.0 + 1e-12);
    EXPECT_GE(q.coordinate_b(p), -1e-12);
    EXPECT_LE(q.coordinate_b(p), 1.0 + 1e-12);
    EXPECT_NEAR(glm::length(y.normal - q.normal()), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(y.pdf_area, 1.0 / (130.0 * 105.0));
  }
}

TEST(LightPointsTest, CapPointsLieOnTheSphereInsideTheCap) {
  const Vec3 c(50, 681.33, 81.6), axis(0, -1, 0);
  Rng rng(2, 0);
  for (int i = 0; i < 1000; ++i) {
    const LightPoint y = sample_sphere_cap(c, 600.0, axis, 0.27, rng.uniform2());
    EXPECT_NEAR(glm::length(y.point - c), 600.0, 1e-9);
    EXPECT_GE(glm::dot(y.point - c, axis), 600.0 - 0.27 - 1e-9);
    EXPECT_NEAR(glm::length(y.normal - (y.point - c) / 600.0), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(y.pdf_area, 1.0 / (k_two_pi * 600.0 * 0.27));
  }
  // The whole unit sphere: pdf 1 / (4 pi).
  EXPECT_DOUBLE_EQ(sphere_cap_pdf_area(1.0, 2.0), 0.25 * k_inv_pi);
}

TEST(LightPointsTest, AreaAndSolidAngleConvertBothWays) {
  // p_w = p_A r^2 / |cos|, and back.
  EXPECT_DOUBLE_EQ(area_to_solid_angle_pdf(0.5, 2.0, 0.25), 0.5 * 4.0 / 0.25);
  EXPECT_DOUBLE_EQ(area_to_solid_angle_pdf(0.5, 2.0, -0.25), 8.0);
  EXPECT_DOUBLE_EQ(solid_angle_to_area_pdf(8.0, 2.0, 0.25), 0.5);
  EXPECT_EQ(area_to_solid_angle_pdf(0.5, 2.0, 0.0), 0.0);  // edge-on: no solid angle
}

// The cone sampler's points lie on the sphere's near side, within the cone, and their area
// pdf is p_w cos(theta_y) / r^2 with p_w = 1 / (2 pi (1 - cos(theta_max))).
TEST(LightPointsTest, ConePointsLieOnTheNearSideWithTheConePdf) {
  const Sphere light = mcrt::testing::cornell_spheres_light();
  const Vec3 x = mcrt::testing::k_above_ceiling;
  const double d = glm::length(light.center - x);
  const double cos_max = std::sqrt(1.0 - light.radius * light.radius / (d * d));
  const double p_w = 1.0 / (k_two_pi * (1.0 - cos_max));
  EXPECT_NEAR(sphere_cone_pdf_solid_angle(light.center, light.radius, x), p_w, 1e-12 * p_w);
  Rng rng(4, 0);
  for (int i = 0; i < 1000; ++i) {
    const LightPoint y = sample_sphere_cone(light.center, light.radius, x, rng.uniform2());
    const Vec3 to_y = y.point - x;
    const double r = glm::length(to_y);
    EXPECT_NEAR(glm::length(y.point - light.center), light.radius, 1e-9);
    EXPECT_GE(glm::dot(to_y / r, glm::normalize(light.center - x)), cos_max - 1e-9);
    const double cos_y = -glm::dot(y.normal, to_y / r);
    EXPECT_GE(cos_y, -1e-9) << "a point of the far side";
    EXPECT_NEAR(y.pdf_area, p_w * cos_y / (r * r), 1e-6 * y.pdf_area);
  }
}

}  // namespace
