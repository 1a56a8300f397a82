// The four paths' bookkeeping (engine/path_lanes.hpp): what shade_lanes and end_lanes do, in
// both engines, and shade_lanes_avx2 / end_lanes_avx2 against the portable versions bit for
// bit, over every mask of live lanes, hits and misses, the depth cut, black, signed-zero and
// NaN weights, and generators in any state.

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/cpu_features.hpp"
#include "core/rng.hpp"
#include "engine/path_lanes.hpp"

using namespace mcrt;

namespace {

constexpr int k_lanes = PathLanes::k_lanes;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// Six materials: black, a lamp, a white diffuser, a coloured one, a glowing coloured one, and
// a glossy one (a Phong lobe beside a diffuse part), whose lanes bounce_lanes weighs apart.
std::vector<Material> test_materials() {
  return {{Color(0.0), Color(0.0)},
          {Color(0.0), Color(12.0, 10.0, 8.0)},
          {Color(1.0), Color(0.0)},
          {Color(0.75, 0.25, 0.5), Color(0.0)},
          {Color(0.3, 0.6, 0.9), Color(0.5, 1.5, 2.5)},
          {Color(0.1, 0.2, 0.1), Color(0.0), 0.7, 300.0}};
}
constexpr std::uint32_t k_material_count = 6;

double weight_for(int i, Rng& rng) {
  switch (i % 9) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return std::numeric_limits<double>::quiet_NaN();
    default: return 3.0 * rng.uniform();
  }
}

// Random lanes: live or not, hit (one of the materials) or missed, any depth up to the cut.
void randomise(int trial, int max_depth, Rng& rng, PathLanes& paths, BounceLanes& bounce) {
  for (int l = 0; l < k_lanes; ++l) {
    paths.start(l, rng.next_bits(), rng.next_bits());
    if (((trial >> l) & 1) == 0) paths.stop(l);  // every mask of live lanes
    paths.depth[l] = rng.uniform_below(static_cast<std::uint32_t>(max_depth) + 1);
    bounce.hit.material[l] =
        static_cast<std::int64_t>(rng.uniform_below(k_material_count + 1)) - 1;  // -1: a miss
    for (int axis = 0; axis < 3; ++axis) {
      paths.radiance[axis][l] = rng.uniform();
      bounce.beta[axis][l] = (trial + l) % 4 == 0 ? weight_for(trial + axis, rng) : rng.uniform();
    }
  }
}

TEST(PathLanesTest, EachLaneDrawsItsPathsRngNumbers) {
  const std::vector<Material> materials = test_materials();
  for (const bool avx2 : {false, true}) {
    if (avx2 && !cpu_has_avx2()) continue;
    PathLanes paths;
    BounceLanes bounce;
    std::vector<Rng> rngs;
    for (int l = 0; l < k_lanes; ++l) {
      const std::uint64_t seed = 7 + l, stream = (static_cast<std::uint64_t>(l) << 32) ^ 99;
      paths.start(l, seed, stream);
      rngs.emplace_back(seed, stream);
      ASSERT_EQ(paths.uniform2(l), rngs[l].uniform2()) << "lane " << l;  // the camera ray's
      bounce.hit.material[l] = 2;                                        // white: all bounce
    }
    for (int step = 0; step < 50; ++step) {
      if (avx2)
        shade_lanes_avx2(materials, 1000, paths, bounce);
      else
        shade_lanes_portable(materials, 1000, paths, bounce);
      for (int l = 0; l < k_lanes; ++l) {
        const Vec2 u = rngs[l].uniform2();
        ASSERT_EQ(bounce.u0[l], u.x) << "lane " << l << " step " << step << " avx2 " << avx2;
        ASSERT_EQ(bounce.u1[l], u.y) << "lane " << l << " step " << step << " avx2 " << avx2;
      }
    }
  }
}

// shade_lanes: a live lane that hit gains beta Le and bounces below the cut, with its
// material's albedo; a miss or an idle lane keeps its radiance and does not bounce. end_lanes:
// the bouncing lanes with a weight that is not black go on, one bounce deeper.
TEST(PathLanesTest, ShadeAndEndFollowTheLoopsRules) {
  const std::vector<Material> materials = test_materials();
  const int max_depth = 3;
  for (const bool avx2 : {false, true}) {
    if (avx2 && !cpu_has_avx2()) continue;
    Rng rng(5, avx2);
    for (int trial = 0; trial < 2000; ++trial) {
      PathLanes paths;
      BounceLanes bounce;
      randomise(trial, max_depth, rng, paths, bounce);
      const PathLanes before = paths;
      if (avx2)
        shade_lanes_avx2(materials, max_depth, paths, bounce);
      else
        shade_lanes_portable(materials, max_depth, paths, bounce);
      for (int l = 0; l < k_lanes; ++l) {
        const bool live = before.live[l] != 0, hit = bounce.hit.material[l] >= 0;
        const bool bounces = live && hit && before.depth[l] != max_depth;
        EXPECT_EQ(bounce.bouncing[l], bounces ? -1 : 0) << trial << " lane " << l;
        for (int axis = 0; axis < 3; ++axis) {
          double expected = before.radiance[axis][l];
          if (live && hit)
            expected += bounce.beta[axis][l] * materials[bounce.hit.material[l]].emission[axis];
          EXPECT_TRUE(same_bits(paths.radiance[axis][l], expected)) << trial << " lane " << l;
          if (bounces) {
            EXPECT_EQ(bounce.albedo[axis][l], materials[bounce.hit.material[l]].albedo[axis]);
          }
        }
        // The lobe goes with the lane exactly where it bounces off a glossy material.
        const bool lobed = bounces && materials[bounce.hit.material[l]].has_lobe();
        EXPECT_EQ((bounce.lobed >> l) & 1u, lobed ? 1u : 0u) << trial << " lane " << l;
        if (lobed) {
          EXPECT_EQ(bounce.specular[l], materials[bounce.hit.material[l]].specular);
          EXPECT_EQ(bounce.exponent[l], materials[bounce.hit.material[l]].exponent);
        }
      }
      const PathLanes shaded = paths;
      const BounceLanes bounced = bounce;
      const unsigned ended =
          avx2 ? end_lanes_avx2(paths, bounce) : end_lanes_portable(paths, bounce);
      for (int l = 0; l < k_lanes; ++l) {
        const bool black =
            bounced.beta[0][l] == 0.0 && bounced.beta[1][l] == 0.0 && bounced.beta[2][l] == 0.0;
        const bool goes_on = bounced.bouncing[l] != 0 && !black;
        EXPECT_EQ((ended >> l) & 1, shaded.live[l] != 0 && !goes_on ? 1u : 0u)
            << trial << " lane " << l;
        EXPECT_EQ(paths.depth[l], goes_on ? shaded.depth[l] + 1 : 0) << trial << " lane " << l;
        for (int axis = 0; axis < 3; ++axis) {
          if (goes_on) {  // the path keeps its estimate and weight
            EXPECT_TRUE(same_bits(paths.radiance[axis][l], shaded.radiance[axis][l])) << trial;
            EXPECT_TRUE(same_bits(bounce.beta[axis][l], bounced.beta[axis][l])) << trial;
          } else {  // its estimate handed in, the lane ready for a new path
            EXPECT_TRUE(same_bits(paths.finished[axis][l], shaded.radiance[axis][l])) << trial;
            EXPECT_EQ(paths.radiance[axis][l], 0.0) << trial;
            EXPECT_EQ(bounce.beta[axis][l], 1.0) << trial;
          }
        }
      }
    }
  }
}

TEST(PathLanesTest, AvxLanesGiveThePortableLanesBits) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor: only the portable lanes run";
  const std::vector<Material> materials = test_materials();
  Rng rng(8, 0);
  for (int trial = 0; trial < 20000; ++trial) {
    const int max_depth = trial % 5;
    PathLanes paths;
    BounceLanes bounce;
    randomise(trial, max_depth, rng, paths, bounce);
    PathLanes fast_paths = paths, plain_paths = paths;
    BounceLanes fast_bounce = bounce, plain_bounce = bounce;
    shade_lanes_avx2(materials, max_depth, fast_paths, fast_bounce);
    shade_lanes_portable(materials, max_depth, plain_paths, plain_bounce);
    for (int l = 0; l < k_lanes; ++l) {
      ASSERT_EQ(fast_bounce.bouncing[l], plain_bounce.bouncing[l]) << trial << " lane " << l;
      ASSERT_EQ((fast_bounce.lobed >> l) & 1u, (plain_bounce.lobed >> l) & 1u)
          << trial << " lane " << l;
      ASSERT_EQ(fast_paths.rng.state[l], plain_paths.rng.state[l]) << trial << " lane " << l;
      for (int axis = 0; axis < 3; ++axis)
        ASSERT_TRUE(same_bits(fast_paths.radiance[axis][l], plain_paths.radiance[axis][l]))
            << trial << " lane " << l;
      if (plain_bounce.bouncing[l] == 0) continue;  // the bounce reads these lanes only
      ASSERT_TRUE(same_bits(fast_bounce.u0[l], plain_bounce.u0[l])) << trial << " lane " << l;
      ASSERT_TRUE(same_bits(fast_bounce.u1[l], plain_bounce.u1[l])) << trial << " lane " << l;
      for (int axis = 0; axis < 3; ++axis)
        ASSERT_TRUE(same_bits(fast_bounce.albedo[axis][l], plain_bounce.albedo[axis][l]));
      if ((plain_bounce.lobed >> l) & 1u) {
        ASSERT_TRUE(same_bits(fast_bounce.specular[l], plain_bounce.specular[l]));
        ASSERT_TRUE(same_bits(fast_bounce.exponent[l], plain_bounce.exponent[l]));
      }
    }
    const unsigned ended = end_lanes_portable(plain_paths, plain_bounce);
    ASSERT_EQ(end_lanes_avx2(fast_paths, fast_bounce), ended) << trial;
    for (int l = 0; l < k_lanes; ++l) {
      ASSERT_EQ(fast_paths.depth[l], plain_paths.depth[l]) << trial;
      for (int axis = 0; axis < 3; ++axis) {
        ASSERT_TRUE(same_bits(fast_paths.radiance[axis][l], plain_paths.radiance[axis][l]))
            << trial;
        ASSERT_TRUE(same_bits(fast_bounce.beta[axis][l], plain_bounce.beta[axis][l])) << trial;
        if ((ended >> l) & 1) {
          ASSERT_TRUE(same_bits(fast_paths.finished[axis][l], plain_paths.finished[axis][l]))
              << trial;
        }
      }
    }
  }
}

TEST(PathLanesTest, ASceneWithoutMaterialsShadesNothing) {
  for (const bool avx2 : {false, true}) {
    if (avx2 && !cpu_has_avx2()) continue;
    PathLanes paths;
    BounceLanes bounce;
    for (int l = 0; l < k_lanes; ++l) {
      paths.start(l, 1, l);
      bounce.hit.material[l] = -1;
    }
    if (avx2)
      shade_lanes_avx2({}, 5, paths, bounce);
    else
      shade_lanes_portable({}, 5, paths, bounce);
    EXPECT_EQ(paths.live_lanes(), 0xfu);
    EXPECT_EQ(avx2 ? end_lanes_avx2(paths, bounce) : end_lanes_portable(paths, bounce), 0xfu);
  }
}

}  // namespace
