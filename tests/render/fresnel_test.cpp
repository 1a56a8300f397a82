// The dielectric boundary (render/fresnel.hpp): Snell's law by construction, the exact Fresnel
// reflectance against its closed forms (normal incidence, total internal reflection, Brewster's
// angle), its reciprocity, and energy conservation R + T = 1 with T computed independently from
// the Fresnel transmission amplitudes. Schlick's approximation, kept for smallpt, is checked
// where it is exact.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "core/math.hpp"
#include "render/fresnel.hpp"

using namespace mcrt;

namespace {

// Index pairs (eta_i, eta_t): into glass, water and diamond, out of them, and nearly equal.
constexpr double k_pairs[][2] = {{1.0, 1.5},  {1.5, 1.0},  {1.0, 1.333}, {1.333, 1.0},
                                 {1.0, 2.42}, {2.42, 1.0}, {1.0, 1.001}, {1.2, 1.7}};

// The formulas are a handful of operations on numbers of size 1: their round-off is a few
// ulps, far below 1e-13.
constexpr double k_tol = 1e-13;

// T from the transmitted amplitudes t_s = 2 n_i c_i / (n_i c_i + n_t c_t),
// t_p = 2 n_i c_i / (n_t c_i + n_i c_t), weighted by the beam's change of cross-section and
// speed, n_t c_t / (n_i c_i): a route to T that shares nothing with R's formula.
double transmittance(double cos_i, double cos_t, double eta_i, double eta_t) {
  const double t_s = 2.0 * eta_i * cos_i / (eta_i * cos_i + eta_t * cos_t);
  const double t_p = 2.0 * eta_i * cos_i / (eta_t * cos_i + eta_i * cos_t);
  return eta_t * cos_t / (eta_i * cos_i) * 0.5 * (t_s * t_s + t_p * t_p);
}

TEST(FresnelTest, NormalIncidenceIsTheSquaredIndexContrast) {
  for (const auto& [eta_i, eta_t] : k_pairs) {
    const double r0 = (eta_t - eta_i) / (eta_t + eta_i);
    EXPECT_NEAR(fresnel_dielectric(1.0, eta_i, eta_t), r0 * r0, k_tol) << eta_i << " " << eta_t;
  }
  // The textbook value for glass, 4 %.
  EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.5), 0.04, k_tol);
}

TEST(FresnelTest, TotalInternalReflectionBeyondTheCriticalAngle) {
  for (const auto& [eta_i, eta_t] : k_pairs) {
    if (eta_i <= eta_t) continue;
    const double sin_critical = eta_t / eta_i;
    const double cos_critical = std::sqrt(1.0 - sin_critical * sin_critical);
    for (double f : {0.999999, 0.9, 0.5, 0.1, 0.0}) {  // cosines below the critical one
      const double cos_i = f * cos_critical;
      EXPECT_FALSE(refracted_cosine(cos_i, eta_i / eta_t)) << cos_i;
      EXPECT_EQ(fresnel_dielectric(cos_i, eta_i, eta_t), 1.0) << cos_i;
    }
    // Just inside the critical angle light still gets through.
    const double inside = std::min(1.0, cos_critical * 1.001);
    EXPECT_LT(fresnel_dielectric(inside, eta_i, eta_t), 1.0);
  }
}

TEST(FresnelTest, ReciprocalBetweenTheTwoSides) {
  for (const auto& [eta_i, eta_t] : k_pairs)
    for (int k = 1; k <= 100; ++k) {
      const double cos_i = k / 100.0;
      const std::optional<double> cos_t = refracted_cosine(cos_i, eta_i / eta_t);
      if (!cos_t) continue;
      // The light that comes back along the refracted ray meets the same boundary. Going back
      // recomputes cos_i from cos_t through a square root (off by ~1e-16 / cos), and R's slope
      // near grazing is ~10: 1e-11 is far above that round-off, far below any wrong index.
      EXPECT_NEAR(fresnel_dielectric(cos_i, eta_i, eta_t), fresnel_dielectric(*cos_t, eta_t, eta_i),
                  1e-11)
          << eta_i << " " << eta_t << " " << cos_i;
    }
}

TEST(FresnelTest, ReflectedAndTransmittedAddToOne) {
  for (const auto& [eta_i, eta_t] : k_pairs)
    for (int k = 1; k <= 1000; ++k) {
      const double cos_i = k / 1000.0;
      const std::optional<double> cos_t = refracted_cosine(cos_i, eta_i / eta_t);
      if (!cos_t) continue;
      const double r = fresnel_dielectric(cos_i, *cos_t, eta_i, eta_t);
      EXPECT_GE(r, 0.0);
      EXPECT_LE(r, 1.0);
      EXPECT_NEAR(r + transmittance(cos_i, *cos_t, eta_i, eta_t), 1.0, 1e-12)
          << eta_i << " " << eta_t << " " << cos_i;
    }
}

TEST(FresnelTest, GrazingIncidenceReflectsEverything) {
  for (const auto& [eta_i, eta_t] : k_pairs) EXPECT_EQ(fresnel_dielectric(0.0, eta_i, eta_t), 1.0);
}

TEST(FresnelTest, BrewstersAngleReflectsNoPPolarisedLight) {
  // At tan(theta_B) = eta_t / eta_i, r_p = 0: R = r_s^2 / 2, and r_s = cos(2 theta_B) there
  // (with sin(theta_t) = cos(theta_B)), so R = cos^2(2 theta_B) / 2.
  const double eta_i = 1.0, eta_t = 1.5;
  const double theta_b = std::atan(eta_t / eta_i);
  const double c2 = std::cos(2.0 * theta_b);
  EXPECT_NEAR(fresnel_dielectric(std::cos(theta_b), eta_i, eta_t), 0.5 * c2 * c2, 1e-12);
}

TEST(FresnelTest, RefractionObeysSnellByConstruction) {
  for (const auto& [eta_i, eta_t] : k_pairs)
    for (int k = 1; k <= 50; ++k) {
      // w at angle theta_i to n = +z, leaning towards +x and a little +y.
      const double cos_i = k / 50.0, sin_i = std::sqrt(1.0 - cos_i * cos_i);
      const Vec3 n(0, 0, 1), w(sin_i * 0.8, sin_i * 0.6, cos_i);
      const double eta = eta_i / eta_t;
      const std::optional<double> cos_t = refracted_cosine(cos_i, eta);
      if (!cos_t) continue;
      const Vec3 t = refract(w, n, cos_i, *cos_t, eta);
      EXPECT_NEAR(glm::length(t), 1.0, k_tol);
      EXPECT_NEAR(-t.z, *cos_t, k_tol);  // on the other side, at theta_t
      const double sin_t = std::hypot(t.x, t.y);
      EXPECT_NEAR(eta_i * sin_i, eta_t * sin_t, k_tol);
      // In the plane of w and n, leaning the other way: the tangent parts are opposite.
      EXPECT_NEAR(t.x * w.y - t.y * w.x, 0.0, k_tol);
      EXPECT_LE(t.x * w.x + t.y * w.y, 0.0);
    }
}

TEST(FresnelTest, ReflectionKeepsTheAngle) {
  const Vec3 n = glm::normalize(Vec3(0.3, -0.2, 0.9));
  const Vec3 w = glm::normalize(Vec3(-0.5, 0.4, 0.7));
  const Vec3 r = reflect(w, n);
  EXPECT_NEAR(glm::length(r), 1.0, k_tol);
  EXPECT_NEAR(glm::dot(r, n), glm::dot(w, n), k_tol);
  EXPECT_NEAR(glm::dot(glm::cross(w, n), r), 0.0, k_tol);  // coplanar with w and n
}

TEST(FresnelTest, SchlickIsExactAtNormalAndGrazingIncidence) {
  for (const auto& [eta_i, eta_t] : k_pairs) {
    const double r0 = (eta_t - eta_i) * (eta_t - eta_i) / ((eta_t + eta_i) * (eta_t + eta_i));
    EXPECT_NEAR(fresnel_schlick(1.0, eta_i, eta_t), r0, k_tol);
    EXPECT_EQ(fresnel_schlick(0.0, eta_i, eta_t), 1.0);
  }
  // In between it approximates: for glass within 0.04 of the exact term at every angle (the
  // largest gap, 0.0357 near 85 degrees, computed on a grid of 10^4 cosines), and within 0.01
  // up to 45 degrees (0.0081 there).
  for (int k = 0; k <= 1000; ++k) {
    const double c = k / 1000.0;
    EXPECT_NEAR(fresnel_schlick(c, 1.0, 1.5), fresnel_dielectric(c, 1.0, 1.5),
                c >= std::sqrt(0.5) ? 0.01 : 0.04)
        << c;
  }
}

}  // namespace
