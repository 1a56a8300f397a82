// The glossy lobe of sampling/phong.hpp: its sampler at the extremes of u and m, its pdf's
// integral, energy conservation and reciprocity of its BRDF. (The chi-square tests of its
// samplers against their pdfs are statistical: tests/sampling/phong_checks.cpp.)

#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/rng.hpp"
#include "sampling/sampling.hpp"
#include "stats/check.hpp"
#include "sampling/phong_lobe.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

constexpr std::array<double, 5> k_exponents{1.0, 10.0, 100.0, 1000.0, 10000.0};

Vec3 random_direction(Rng& rng) { return sample_uniform_sphere(rng.uniform2()); }

// ---- the sampler ----

// sin(alpha) must keep its digits where cos(alpha) is within 1e-14 of 1 (m = 1e4, u0 near 1).
// The reference 1 - cos(alpha) = -expm1(log1p(-(1 - u0)) / (m + 1)) in long double. The
// sampler's x^2 + y^2 = sin^2(alpha) carries a few ulps from log, expm1, sqrt and
// cos_sin_two_pi (< 2e-15 relative); 1e-13 leaves room. sqrt(1 - cos^2) would be off by 1 %
// at u0 = 1 - 2^-32, m = 1e4.
TEST(PhongTest, SinAlphaKeepsItsDigitsNearTheAxis) {
  const std::array<double, 6> u0s{0x1p-32, 1e-3, 0.5, 1.0 - 1e-6, 1.0 - 0x1p-32, 1.0 - 0x1p-53};
  for (double m : k_exponents)
    for (double u0 : u0s) {
      const Vec3 w = sample_phong_lobe_local({u0, 0.3}, m);
      const long double one_minus_cos =
          -std::expm1(std::log1p(-(1.0L - static_cast<long double>(u0))) / (m + 1.0L));
      const long double sin2 = one_minus_cos * (2.0L - one_minus_cos);
      const double got = w.x * w.x + w.y * w.y;
      EXPECT_NEAR(got / static_cast<double>(sin2), 1.0, 1e-13) << "m " << m << " u0 " << u0;
      EXPECT_NEAR(glm::length(w), 1.0, 1e-15) << "m " << m << " u0 " << u0;  // a few ulps
    }
}

// u0 = 0 is the lobe's horizon (cos alpha = 0), u0 near 1 its axis; every u gives a finite
// unit direction at every m, and its pdf is finite.
TEST(PhongTest, SamplerIsFiniteAtTheEndsOfU) {
  const Vec3 r = phong_test_reflected();
  const std::array<Vec2, 4> us{Vec2(0.0, 0.0), Vec2(0.0, 0.999), Vec2(1.0 - 0x1p-53, 0.5),
                               Vec2(0x1p-1074, 0.25)};
  for (double m : k_exponents)
    for (Vec2 u : us) {
      const Vec3 w = sample_phong_lobe(u, r, m);
      ASSERT_TRUE(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z));
      EXPECT_NEAR(glm::length(w), 1.0, 1e-15);  // a few ulps of the frame's rotation
      EXPECT_TRUE(std::isfinite(phong_lobe_pdf(w, r, m)));
    }
  EXPECT_NEAR(glm::dot(sample_phong_lobe({0.0, 0.3}, r, 100.0), r), 0.0, 1e-15);
}

// pow of a tiny cosine underflows to 0, never NaN or infinity; below the lobe's horizon the
// pdf is exactly 0; on its axis it is (m + 1)/(2 pi).
TEST(PhongTest, LobePdfAtTheEdgesOfCosAlpha) {
  const Vec3 r(0.0, 0.0, 1.0);
  for (double m : k_exponents) {
    EXPECT_EQ(phong_lobe_pdf(r, r, m), (m + 1.0) * k_inv_two_pi);
    const double tiny = phong_lobe_pdf(Vec3(1.0, 0.0, 1e-300), r, m);  // cos alpha = 1e-300
    EXPECT_TRUE(std::isfinite(tiny) && tiny >= 0.0 && tiny < 1e-299);
    EXPECT_EQ(phong_lobe_pdf(Vec3(1.0, 0.0, 0.0), r, m), 0.0);
    EXPECT_EQ(phong_lobe_pdf(glm::normalize(Vec3(1.0, 0.0, -1e-3)), r, m), 0.0);
    EXPECT_EQ(phong_lobe_pdf(-r, r, m), 0.0);
  }
}

// ---- the pdf integrates to 1 ----

// The lobe pdf over the whole sphere, in a basis round r: dw = dphi d(cos alpha), and with
// cos(alpha) = exp(-v / (m + 1)), d(cos alpha) = cos(alpha) / (m + 1) dv: an exact change of
// variables that makes the integrand of a right pdf e^-v / (2 pi) at every m (the lobe is
// 1e-4 wide at m = 1e4) and keeps a wrong one visible (an m + 2 normalisation gives
// (m + 2)/(m + 1), a cos^(m+1) lobe (m + 1)/(m + 2)). v in [0, 50] (the rest holds e^-50 of
// it) by adaptive 31-point Gauss-Kronrod to relative tolerance 1e-12, phi by one 15-point
// rule, exact for the pdf's constant in phi. The quadrature's own error estimate is 1e-13;
// the round-off of cos(alpha) (a few ulps from the rotation round r) is raised to the m-th
// power, so the total error grows with m: measured 2e-15 at m = 1, 1.3e-11 at m = 1e4.
// 1e-10 passes that and fails an m + 2 normalisation (off by 1e-4 at m = 1e4). Below the
// lobe's horizon the pdf must be 0.
TEST(PhongTest, LobePdfIntegratesToOneOverTheSphere) {
  using Quadrature = boost::math::quadrature::gauss_kronrod<double, 31>;
  using Rule = boost::math::quadrature::gauss_kronrod<double, 15>;
  const Vec3 r = phong_test_reflected();
  const AxisBasis basis(r, phong_test_normal());
  for (double m : k_exponents) {
    const auto over_phi = [&](double v) {
      const double log_c = -v / (m + 1.0);
      const double c = std::exp(log_c);
      const double s = std::sqrt(-std::expm1(log_c) * (1.0 + c));
      const auto pdf = [&](double phi) {
        return phong_lobe_pdf(basis.to_world({s * std::cos(phi), s * std::sin(phi), c}), r, m);
      };
      return Rule::integrate(pdf, 0.0, k_two_pi, 0, 0.0) * c / (m + 1.0);
    };
    const double total = Quadrature::integrate(over_phi, 0.0, k_lobe_v_max, 10, 1e-12);
    EXPECT_NEAR(total, 1.0, 1e-10) << "m " << m;
    for (int i = 1; i <= 100; ++i)   // from cos(alpha) = -0.01: at 0 the rotation's round-off
      for (int j = 0; j < 8; ++j) {  // may land either side of the horizon
        const double c = -i / 100.0;
        const double s = std::sqrt((1.0 - c) * (1.0 + c));
        const double phi = j * k_two_pi / 8.0;
        EXPECT_EQ(phong_lobe_pdf(basis.to_world({s * std::cos(phi), s * std::sin(phi), c}), r, m),
                  0.0);
      }
  }
}

// ---- energy conservation ----

// A white lobe (rho_s = 1) reflects at most what it receives: a(theta_o) <= 1 at every angle
// of incidence, exactly 1 at normal incidence (the closed form: (m + 2)/(m + 1) E[cos alpha]),
// and less and less towards grazing, where part of the lobe is below the horizon and the rest
// meets the surface at a grazing angle. phong_lobe_albedo's quadrature is accurate to ~1e-10
// (its pieces are smooth; at normal incidence it is measured within 1.4e-13 of the exact 1 at
// every m), so 1e-9 is the slack.
TEST(PhongTest, WhiteLobeReflectsAtMostOneAtEveryIncidence) {
  const std::array<double, 12> degrees{0, 5, 15, 25, 35, 45, 55, 65, 75, 85, 89, 89.9};
  for (double m : k_exponents) {
    const Phong white{0.0, 1.0, m};
    double previous = 1.0 + 1e-9;
    for (double d : degrees) {
      const double albedo = phong_lobe_albedo(white, d * k_pi / 180.0);
      SCOPED_TRACE(::testing::Message() << "m " << m << " theta_o " << d);
      EXPECT_LE(albedo, 1.0 + 1e-9);
      if (d == 0.0) {
        EXPECT_NEAR(albedo, 1.0, 1e-9);
      } else {
        EXPECT_LT(albedo, 1.0 - 1e-6);  // strictly below: some light is lost
      }
      EXPECT_LE(albedo, previous);  // each step of theta_o loses more
      previous = albedo + 1e-9;
    }
    // At grazing incidence most of the light is lost (a ~ cos(theta_r) for a sharp lobe,
    // half the lobe below the horizon for a rough one).
    EXPECT_LT(phong_lobe_albedo(white, 89.0 * k_pi / 180.0), 0.5) << "m " << m;
  }
}

// ---- reciprocity ----

// f(wi, wo) == f(wo, wi) to the last bit: phong_cos_alpha does the same operations in the
// same order for both (IEEE products commute), so the bound is 0, not a few ulps. Random
// normals and directions, both above the surface, 1e4 pairs.
TEST(PhongTest, BrdfIsReciprocal) {
  Rng rng(k_suite_seed, 31);
  int above = 0;
  for (int k = 0; k < 10000; ++k) {
    const Vec3 n = random_direction(rng);
    Vec3 wi = random_direction(rng), wo = random_direction(rng);
    if (glm::dot(wi, n) < 0.0) wi = -wi;
    if (glm::dot(wo, n) < 0.0) wo = -wo;
    const double m = k_exponents[static_cast<std::size_t>(k) % k_exponents.size()];
    const Phong material{0.3 * rng.uniform(), 0.7 * rng.uniform(), m};
    const double f = phong_brdf(material, wi, wo, n);
    ASSERT_EQ(f, phong_brdf(material, wo, wi, n)) << "pair " << k;
    if (f > material.rho_d * k_inv_pi) ++above;
  }
  EXPECT_GT(above, 1000);  // the lobe itself was seen, not only the diffuse part
}

// f = 0 when either direction is below the surface, and 0 on the horizon.
TEST(PhongTest, BrdfIsZeroBelowTheSurface) {
  const Vec3 n(0.0, 0.0, 1.0);
  const Phong material{0.2, 0.8, 10.0};
  const Vec3 up = glm::normalize(Vec3(0.3, 0.1, 1.0));
  const Vec3 down = glm::normalize(Vec3(-0.3, -0.1, -1.0));
  EXPECT_GT(phong_brdf(material, up, up, n), 0.0);
  EXPECT_EQ(phong_brdf(material, down, up, n), 0.0);
  EXPECT_EQ(phong_brdf(material, up, down, n), 0.0);
  EXPECT_EQ(phong_brdf(material, Vec3(1.0, 0.0, 0.0), up, n), 0.0);
}

// The BRDF's lobe is the lobe the sampler draws: f_lobe = rho_s (m + 2)/(m + 1) p_lobe for
// every wi above the surface. The two compute cos alpha in different orders (and wo is r
// reflected back, itself rounded), a few ulps apart; cos^m multiplies that by m: 1e-10
// relative covers m = 1e4 times 20 ulps.
TEST(PhongTest, BrdfLobeIsProportionalToTheLobePdf) {
  Rng rng(k_suite_seed, 32);
  const Vec3 n = phong_test_normal();
  const Vec3 r = phong_test_reflected();
  const Vec3 wo = mirror_direction(r, n);
  for (double m : k_exponents) {
    const Phong lobe{0.0, 0.9, m};
    for (int k = 0; k < 1000; ++k) {
      const Vec3 wi = sample_phong_lobe(rng.uniform2(), r, m);
      const double f = phong_brdf(lobe, wi, wo, n);
      if (glm::dot(wi, n) <= 0.0) {
        EXPECT_EQ(f, 0.0);
        continue;
      }
      const double expected = 0.9 * (m + 2.0) / (m + 1.0) * phong_lobe_pdf(wi, r, m);
      EXPECT_NEAR(f, expected, 1e-10 * expected) << "m " << m;
    }
  }
}

// The full material's pdf integrates to 1 over the sphere: P_s x 1 + (1 - P_s) x 1. Gauss-
// Kronrod on 21 x 21 (phi, z) cells round n (stats/chi_square.hpp, tolerance 1e-10 per cell);
// the lobe at m = 10 is smooth on that scale, so 1e-8 is ample and fails a wrong mixture.
TEST(PhongTest, MaterialPdfIntegratesToOne) {
  const Vec3 n = phong_test_normal();
  const AxisBasis basis(n, Vec3(1, 0, 0));
  const Vec3 wo = basis.to_world({std::sin(0.7), 0.0, std::cos(0.7)});
  for (const Phong& material : {Phong{0.5, 0.3, 10.0}, Phong{0.0, 1.0, 10.0}, Phong{0.6, 0.0, 10.0},
                                Phong{0.0, 0.0, 10.0}}) {
    const auto pdf = [&](const Vec3& local) {
      return phong_pdf(material, basis.to_world(local), n, wo);
    };
    EXPECT_NEAR(pdf_integral(pdf, sphere_binning(21, 21)), 1.0, 1e-8)
        << "rho_d " << material.rho_d << " rho_s " << material.rho_s;
  }
}

// The closed forms of the albedo estimator at normal incidence: E[Y] = rho_s,
// Var[Y] = rho_s^2 / ((m + 1)(m + 3)), checked against quadrature of Y's first two moments
// over cos(alpha) (density (m + 1) c^m; Y = rho_s (m + 2)/(m + 1) c); and the bound holds.
TEST(PhongTest, AlbedoVarianceClosedFormAtNormalIncidence) {
  using Quadrature = boost::math::quadrature::gauss_kronrod<double, 31>;
  for (double m : {1.0, 10.0, 100.0}) {
    const double rho_s = 0.8;
    const double y_per_c = rho_s * (m + 2.0) / (m + 1.0);
    const auto moment = [&](int k) {
      return Quadrature::integrate(
          [&](double c) { return (m + 1.0) * std::pow(c, m) * std::pow(y_per_c * c, k); }, 0.0, 1.0,
          15, 1e-14);
    };
    const double mean = moment(1);
    EXPECT_NEAR(mean, rho_s, 1e-12);
    EXPECT_NEAR(moment(2) - mean * mean, phong_lobe_albedo_variance_at_normal(rho_s, m), 1e-12);
    EXPECT_LE(phong_lobe_albedo_variance_at_normal(rho_s, m),
              phong_lobe_albedo_variance_bound(rho_s, rho_s, m));
  }
}

}  // namespace
