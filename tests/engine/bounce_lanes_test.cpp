// The four-lane bounce (engine/bounce_lanes.hpp): bounce_lanes_avx2 against
// bounce_lanes_portable, which runs the one-path code (sample_uniform_hemisphere, Frame,
// spawn_ray, the weight update) lane by lane. Both must give the same bits in every lane: the
// new ray and weight where a lane bounces, and the old ones, untouched, where it does not.
//
// The inputs reach the corners of the code: normals along and against every axis (Frame's
// branch-free sign at n.z = +-1 and +-0), u1 at the quarter turns of cos_sin_two_pi and just
// below 1, u0 at 0 (a grazing direction), hit points far from the origin (the offset grows
// with them), black and white albedos, and every mask of bouncing lanes.

#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/cpu_features.hpp"
#include "core/rng.hpp"
#include "engine/bounce_lanes.hpp"
#include "render/material.hpp"
#include "sampling/phong.hpp"
#include "sampling/sampling.hpp"

using namespace mcrt;

namespace {

bool same_bits(const double* a, const double* b, int n) {
  return std::memcmp(a, b, n * sizeof(double)) == 0;
}

// A unit normal: a random one, or one of the special ones.
Vec3 normal_for(int i, Rng& rng) {
  static const std::vector<Vec3> special{{0, 0, 1}, {0, 0, -1}, {1, 0, 0},   {-1, 0, 0},
                                         {0, 1, 0}, {0, -1, 0}, {1, 0, 0.0}, {1, 0, -0.0}};
  if (i % 3 == 0) return special[rng.uniform_below(static_cast<std::uint32_t>(special.size()))];
  return sample_uniform_sphere(rng.uniform2());
}

double u1_for(int i, Rng& rng) {
  static const double special[] = {0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0 - 0x1p-32};
  return i % 4 == 0 ? special[rng.uniform_below(9)] : rng.uniform();
}

TEST(BounceLanesTest, AvxLanesGiveTheOnePathCodesBits) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor: only the portable lanes run";
  Rng rng(21, 0);
  for (int trial = 0; trial < 20000; ++trial) {
    BounceLanes lanes;
    RayLanes rays;
    for (int l = 0; l < k_bounce_lanes; ++l) {
      const Vec3 n = normal_for(trial + l, rng);
      const double reach = trial % 5 == 0 ? 1e5 : 600.0;  // the sphere box's walls: 1e5 away
      for (int axis = 0; axis < 3; ++axis) {
        lanes.hit.point[axis][l] = reach * (2.0 * rng.uniform() - 1.0);
        lanes.hit.normal[axis][l] = n[axis];
        lanes.albedo[axis][l] = (trial + axis) % 7 == 0 ? 0.0 : rng.uniform();
        lanes.beta[axis][l] = 3.0 * rng.uniform();
      }
      lanes.u0[l] = (trial + l) % 11 == 0 ? 0.0 : rng.uniform();
      lanes.u1[l] = u1_for(trial + l, rng);
      lanes.bouncing[l] =
          -static_cast<std::int64_t>((trial >> l) & 1);  // every mask of the four lanes
      rays.set(l, Ray(Vec3(rng.uniform()), Vec3(0, 1, 0)));
    }
    BounceLanes fast_lanes = lanes, plain_lanes = lanes;
    RayLanes fast_rays = rays, plain_rays = rays;
    bounce_lanes_avx2(fast_lanes, fast_rays);
    bounce_lanes_portable(plain_lanes, plain_rays);
    for (int axis = 0; axis < 3; ++axis)
      ASSERT_TRUE(same_bits(fast_lanes.beta[axis], plain_lanes.beta[axis], k_bounce_lanes))
          << "trial " << trial << " beta axis " << axis;
    ASSERT_TRUE(same_bits(fast_rays.origin_x, plain_rays.origin_x, k_bounce_lanes)) << trial;
    ASSERT_TRUE(same_bits(fast_rays.origin_y, plain_rays.origin_y, k_bounce_lanes)) << trial;
    ASSERT_TRUE(same_bits(fast_rays.origin_z, plain_rays.origin_z, k_bounce_lanes)) << trial;
    ASSERT_TRUE(same_bits(fast_rays.direction_x, plain_rays.direction_x, k_bounce_lanes)) << trial;
    ASSERT_TRUE(same_bits(fast_rays.direction_y, plain_rays.direction_y, k_bounce_lanes)) << trial;
    ASSERT_TRUE(same_bits(fast_rays.direction_z, plain_rays.direction_z, k_bounce_lanes)) << trial;
  }
}

// Lanes that bounce off a glossy lobe (the bit `lobed`): both engines give the one-path loop's
// line, beta * (f_r(wi, wo, n) cos(theta_i) / pdf) with Material::f_r, bit for bit; wi is the
// one-path sampler's direction and wo the reverse of the ray that reached the hit. The rays
// arrive against the normal (as Hit::normal faces them) and the lobes are sharp and rough, so
// many directions fall inside a lobe and its value, not only the diffuse part, is compared.
TEST(BounceLanesTest, LobedLanesGiveTheOnePathLoopsWeight) {
  Rng rng(22, 0);
  int inside_a_lobe = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    BounceLanes lanes;
    RayLanes rays;
    Color expected[k_bounce_lanes];
    for (int l = 0; l < k_bounce_lanes; ++l) {
      const Vec3 n = normal_for(trial + l, rng);
      Material m;
      m.albedo = (trial + l) % 3 == 0 ? Color(0.0) : Color(0.2 * rng.uniform());
      m.specular = 0.8 * rng.uniform();
      m.exponent = (trial + l) % 2 == 0 ? 1.0 + 20.0 * rng.uniform() : 1e3;
      Vec3 d = sample_uniform_sphere(rng.uniform2());
      if (glm::dot(d, n) > 0.0) d = -d;  // arriving from the normal's side
      lanes.u0[l] = (trial + l) % 11 == 0 ? 0.0 : rng.uniform();
      lanes.u1[l] = u1_for(trial + l, rng);
      const Vec3 local = sample_uniform_hemisphere({lanes.u0[l], lanes.u1[l]});
      const Vec3 wi = Frame(n).to_world(local);
      // A sharp lobe is met only near the mirror direction: half of the rays arrive so that wi
      // is exactly their mirror direction, the lobe's peak.
      if (trial % 2 == 0) d = -mirror_direction(wi, n);
      for (int axis = 0; axis < 3; ++axis) {
        lanes.hit.point[axis][l] = 10.0 * (2.0 * rng.uniform() - 1.0);
        lanes.hit.normal[axis][l] = n[axis];
        lanes.albedo[axis][l] = m.albedo[axis];
        lanes.beta[axis][l] = 3.0 * rng.uniform();
      }
      lanes.bouncing[l] = -static_cast<std::int64_t>((trial >> l) & 1);
      if ((trial >> (l + 4)) & 1) {  // every mask of lobed lanes among them
        lanes.lobed |= 1u << l;
        lanes.specular[l] = m.specular;
        lanes.exponent[l] = m.exponent;
      } else {
        m.specular = 0.0;  // a diffuse lane
      }
      rays.set(l, Ray(Vec3(rng.uniform()), d));
      const Color beta(lanes.beta[0][l], lanes.beta[1][l], lanes.beta[2][l]);
      const Color f = m.f_r(wi, -d, n);
      inside_a_lobe += m.has_lobe() && f != m.brdf();
      // estimate_path_radiance's line: beta *= f_r * cos_theta_i / pdf, cos_theta_i = local.z.
      expected[l] = lanes.bouncing[l] != 0 ? beta * (f * local.z / uniform_hemisphere_pdf()) : beta;
    }
    for (const bool avx2 : {false, true}) {
      if (avx2 && !cpu_has_avx2()) continue;
      BounceLanes out = lanes;
      RayLanes out_rays = rays;
      if (avx2)
        bounce_lanes_avx2(out, out_rays);
      else
        bounce_lanes_portable(out, out_rays);
      for (int l = 0; l < k_bounce_lanes; ++l)
        for (int axis = 0; axis < 3; ++axis)
          ASSERT_TRUE(same_bits(&out.beta[axis][l], &expected[l][axis], 1))
              << "trial " << trial << " lane " << l << " axis " << axis << " avx2 " << avx2;
    }
  }
  EXPECT_GT(inside_a_lobe, 1000);  // the lobes' values were compared, not only rho / pi
}

// The portable lanes do bounce: a lane that bounces gets a unit direction on the normal's side,
// an origin within the offset of the hit point, and the weight times 2 rho cos(theta); one
// that does not keeps its ray and weight.
TEST(BounceLanesTest, BouncingLanesMoveAndTheOthersStay) {
  BounceLanes lanes;
  RayLanes rays;
  const Ray old(Vec3(7.0), Vec3(0, 1, 0));
  for (int l = 0; l < k_bounce_lanes; ++l) {
    lanes.hit.normal[1][l] = 1.0;  // n = +y at the point (l, 0, 0)
    lanes.hit.point[0][l] = l;
    for (int axis = 0; axis < 3; ++axis) {
      lanes.albedo[axis][l] = 0.5;
      lanes.beta[axis][l] = 1.0;
    }
    lanes.u0[l] = 0.25 * (l + 1);  // cos(theta)
    lanes.u1[l] = 0.1 * l;
    lanes.bouncing[l] = l % 2 == 0 ? -1 : 0;
    rays.set(l, old);
  }
  bounce_lanes(lanes, rays);
  for (int l = 0; l < k_bounce_lanes; ++l) {
    const Ray ray = rays.get(l);
    if (lanes.bouncing[l] == 0) {
      EXPECT_EQ(ray.origin, old.origin);
      EXPECT_EQ(ray.direction, old.direction);
      EXPECT_EQ(lanes.beta[0][l], 1.0);
      continue;
    }
    EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-15);  // a few roundings of a unit vector
    EXPECT_NEAR(ray.direction.y, lanes.u0[l], 1e-15);     // cos(theta) along the normal
    EXPECT_NEAR(ray.origin.x, l, 1e-6);                   // offset 1e-7 (1 + |p|) at most
    EXPECT_GT(ray.origin.y, 0.0);                         // pushed to the normal's side
    EXPECT_NEAR(lanes.beta[1][l], 2.0 * 0.5 * lanes.u0[l], 1e-15);  // 2 rho cos(theta)
  }
}

}  // namespace
