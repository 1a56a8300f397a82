// The starts of a row's paths (engine/path_starts.hpp): both engines against render()'s own
// two lines, Rng(seed, stream) and camera.generate_ray(x, y, rng.uniform2()), bit for bit, for
// every count of a block (whole passes of four and not), cameras with and without a near
// plane, one and several samples per pixel, sample numbers past 2^32 / 2 and large seeds.

#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/cpu_features.hpp"
#include "core/pcg32_lanes.hpp"
#include "core/rng.hpp"
#include "engine/path_starts.hpp"

using namespace mcrt;

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

struct Case {
  CameraSpec spec;
  int width, height, y;
  RenderSettings settings;
  RowSample first;
};

std::vector<Case> cases() {
  CameraSpec box{{50.0, 52.0, 295.6}, {0.0, -0.042612, -1.0}, {0.0, 1.0, 0.0}, 0.5135, 140.0};
  CameraSpec tilted{{1.0, 2.0, 3.0}, {0.3, -0.2, -1.0}, {0.1, 1.0, 0.0}, 1.1, 0.0};
  RenderSettings one;
  one.spp = 1;
  one.seed = 1;
  RenderSettings several;
  several.spp = 7;
  several.seed = 0xfedcba9876543210ULL;
  several.first_sample = 0x80000005ULL;
  RenderSettings many = one;  // a row of 3 pixels holds a whole block
  many.spp = 25;
  return {{box, 256, 192, 0, one, {0, 0}},
          {box, 256, 192, 191, several, {240, 3}},
          {tilted, 37, 11, 5, several, {2, 6}},
          {tilted, 3, 2, 1, many, {0, 0}}};
}

void check_engine(bool avx2) {
  for (const Case& c : cases()) {
    const Camera camera(c.spec, c.width, c.height);
    for (int count = 1; count <= PathStarts::k_capacity; ++count) {
      RowSample next = c.first;
      PathStarts starts;
      if (avx2)
        make_path_starts_avx2(camera, c.settings, c.y, next, count, starts);
      else
        make_path_starts_portable(camera, c.settings, c.y, next, count, starts);
      RowSample expected = c.first;
      for (int i = 0; i < count; ++i, expected.advance(c.settings.spp)) {
        // render()'s lines for this sample
        const std::uint64_t pixel = static_cast<std::uint64_t>(c.y) * c.width + expected.x;
        Rng rng(c.settings.seed, stream_index(pixel, c.settings.first_sample + expected.sample));
        const Ray ray = camera.generate_ray(expected.x, c.y, rng.uniform2());
        const Ray made = starts.ray(i);
        for (int axis = 0; axis < 3; ++axis) {
          ASSERT_TRUE(same_bits(made.origin[axis], ray.origin[axis]))
              << "avx2 " << avx2 << " count " << count << " start " << i << " axis " << axis;
          ASSERT_TRUE(same_bits(made.direction[axis], ray.direction[axis]))
              << "avx2 " << avx2 << " count " << count << " start " << i << " axis " << axis;
        }
        // the generator goes on as the sample's Rng does
        Pcg32Lanes<1> resumed;
        resumed.state[0] = starts.state[i];
        resumed.increment[0] = starts.increment[i];
        for (int draw = 0; draw < 4; ++draw)
          ASSERT_EQ(resumed.next(0), rng.next_bits())
              << "avx2 " << avx2 << " count " << count << " start " << i << " draw " << draw;
      }
      EXPECT_EQ(next.x, expected.x) << "count " << count;
      EXPECT_EQ(next.sample, expected.sample) << "count " << count;
    }
  }
}

TEST(PathStartsTest, PortableStartsAreRendersGeneratorAndCameraRay) { check_engine(false); }

TEST(PathStartsTest, Avx2StartsAreRendersGeneratorAndCameraRay) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor";
  check_engine(true);
}

TEST(PathStartsTest, RowSampleCountsSamplesThenPixels) {
  RowSample s;
  for (int i = 0; i < 3; ++i) s.advance(3);
  EXPECT_EQ(s.x, 1);
  EXPECT_EQ(s.sample, 0);
  s.advance(3);
  EXPECT_EQ(s.x, 1);
  EXPECT_EQ(s.sample, 1);
}

}  // namespace
