// Material (render/material.hpp): a diffuse albedo with an optional Phong lobe. Without a lobe
// f_r is brdf() = rho / pi itself, bit for bit, whatever the directions, and the cosine bounce
// weight is the albedo itself: so every diffuse scene renders the same bits as before the lobe
// existed. With one, f_r is rho / pi plus sampling/phong.hpp's lobe, reciprocal, peaked at the
// mirror direction, and 0 for the lobe below the surface.

#include <gtest/gtest.h>

#include <cstring>

#include "core/rng.hpp"
#include "render/material.hpp"
#include "sampling/phong.hpp"
#include "sampling/sampling.hpp"

using namespace mcrt;

namespace {

bool same_bits(const Color& a, const Color& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(MaterialTest, WithoutALobeFrIsBrdfBitForBit) {
  Rng rng(1, 0);
  for (int i = 0; i < 10000; ++i) {
    Material m{Color(rng.uniform(), rng.uniform(), rng.uniform()), Color(0.0)};
    m.exponent = 1.0 + 1e4 * rng.uniform();  // ignored while specular is 0
    ASSERT_FALSE(m.has_lobe());
    // Any directions, above or below the surface: the diffuse f_r does not look at them.
    const Vec3 n = sample_uniform_sphere(rng.uniform2());
    const Vec3 wi = sample_uniform_sphere(rng.uniform2()),
               wo = sample_uniform_sphere(rng.uniform2());
    ASSERT_TRUE(same_bits(m.f_r(wi, wo, n), m.brdf())) << i;
    ASSERT_TRUE(same_bits(m.f_r(wi, wo, n), m.albedo * k_inv_pi)) << i;
    ASSERT_TRUE(same_bits(cosine_bounce_weight(m, wi, wo, n), m.albedo)) << i;
  }
}

TEST(MaterialTest, WithALobeFrIsDiffusePlusThePhongLobe) {
  Rng rng(2, 0);
  int peaked = 0;
  for (int i = 0; i < 10000; ++i) {
    Material m{Color(0.2 * rng.uniform()), Color(0.0), 0.8 * rng.uniform() + 1e-3,
               1.0 + 1000.0 * rng.uniform()};
    ASSERT_TRUE(m.has_lobe());
    const Vec3 n = sample_uniform_sphere(rng.uniform2());
    const Frame frame(n);
    const Vec3 wi = frame.to_world(sample_uniform_hemisphere(rng.uniform2()));
    const Vec3 wo = i % 2 == 0 ? frame.to_world(sample_uniform_hemisphere(rng.uniform2()))
                               : mirror_direction(wi, n);  // at the lobe's peak
    const double lobe = phong_brdf(Phong{0.0, m.specular, m.exponent}, wi, wo, n);
    const Color f = m.f_r(wi, wo, n);
    ASSERT_EQ(f, m.albedo * k_inv_pi + Color(lobe)) << i;
    ASSERT_EQ(f, m.f_r(wo, wi, n)) << i;        // reciprocity, bit for bit (phong.hpp's cos alpha)
    if (i % 2 == 1 && glm::dot(wi, n) > 0.1) {  // the peak: rho_s (m + 2) / (2 pi)
      EXPECT_NEAR(lobe, m.specular * (m.exponent + 2.0) * k_inv_two_pi,
                  1e-9 * m.specular * (m.exponent + 2.0));  // pow's round-off, m times cos's
      ++peaked;
    }
    // pi f_r: the cosine bounce weight with the lobe.
    ASSERT_EQ(cosine_bounce_weight(m, wi, wo, n), f * k_pi) << i;
  }
  EXPECT_GT(peaked, 3000);
  // Below the surface the lobe is 0 and only the diffuse part is left.
  const Material m{Color(0.1), Color(0.0), 0.5, 10.0};
  const Vec3 n(0, 0, 1), up(0, 0, 1), down(0, 0, -1);
  EXPECT_EQ(m.f_r(down, up, n), m.brdf());
  EXPECT_EQ(m.f_r(up, down, n), m.brdf());
  EXPECT_GT(m.f_r(up, up, n).r, m.brdf().r);  // wi = wo = n: the mirror direction, the peak
}

}  // namespace
