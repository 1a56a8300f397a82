// The padded samples of a path (sampling/path_sampler.hpp): every 2D set of a pixel's samples
// stratified exactly (jittered: one sample per grid cell; sobol at spp = 2^m: one per
// elementary box), the sets of two bounces scrambled differently (padding), the same samples
// whatever order they are made in, and the names --sampler accepts.

#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/math.hpp"
#include "sampling/path_sampler.hpp"
#include "sampling/sobol_matrices.hpp"

using namespace mcrt;

namespace {

// Set `set` of a pixel's `count` samples: sample s's point in it.
std::vector<Vec2> set_points(PathSampler kind, std::uint64_t pixel_key, std::uint32_t count,
                             unsigned set) {
  std::vector<Vec2> points;
  PaddedPixel pixel(kind, pixel_key, count);
  for (std::uint32_t s = 0; s < count; ++s) {
    PaddedSample sample(pixel, s);
    for (unsigned k = 0; k < set; ++k) sample.uniform2();
    points.push_back(sample.uniform2());
  }
  return points;
}

// Whether the points hold exactly one point in each of the nx x ny cells of [0,1)^2.
bool one_per_cell(const std::vector<Vec2>& points, std::uint32_t nx, std::uint32_t ny) {
  std::vector<int> count(std::size_t{nx} * ny, 0);
  for (const Vec2& p : points) {
    if (!(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0)) return false;
    ++count[static_cast<std::size_t>(std::floor(p.y * ny)) * nx +
            static_cast<std::size_t>(std::floor(p.x * nx))];
  }
  for (int c : count)
    if (c != 1) return false;
  return true;
}

TEST(PathSamplerTest, NamesRoundTripAndUnknownNamesAreRefused) {
  for (PathSampler sampler : k_path_samplers)
    EXPECT_EQ(path_sampler_named(name_of(sampler)), sampler);
  EXPECT_FALSE(path_sampler_named("halton").has_value());
  EXPECT_FALSE(path_sampler_named("").has_value());
}

// Jittered: the pixel position and every bounce's direction one sample per cell of the grid
// (4 x 4 at 16 spp, 2 x 3 at 6 spp: columns the largest divisor of spp not above sqrt(spp)).
TEST(PathSamplerTest, JitteredSetsHoldOneSamplePerCell) {
  for (std::uint64_t key : {1ull, 7ull, 12345ull})
    for (unsigned set = 0; set < 6; ++set) {
      EXPECT_TRUE(one_per_cell(set_points(PathSampler::jittered, key, 16, set), 4, 4)) << set;
      EXPECT_TRUE(one_per_cell(set_points(PathSampler::jittered, key, 6, set), 2, 3)) << set;
    }
}

// Sobol' at spp = 2^m: every set a (0,m,2)-net, one sample in each elementary box of area 2^-m.
TEST(PathSamplerTest, SobolSetsAreNetsAtPowersOfTwo) {
  for (std::uint64_t key : {1ull, 7ull, 12345ull})
    for (unsigned set = 0; set < 6; ++set)
      for (unsigned m : {2u, 4u, 6u}) {
        const std::vector<Vec2> points = set_points(PathSampler::sobol, key, 1u << m, set);
        for (unsigned k = 0; k <= m; ++k)
          EXPECT_TRUE(one_per_cell(points, 1u << k, 1u << (m - k)))
              << "set " << set << " m " << m << " box 2^-" << k << " x 2^-" << (m - k);
      }
}

// The padded Sobol' sets take dimension 0 as the reversed bits of the index (van der Corput),
// which is what Boost's first Sobol' dimension is.
TEST(PathSamplerTest, SobolDimensionZeroIsTheReversedIndex) {
  for (std::uint32_t i = 0; i < 4096; ++i) ASSERT_EQ(sobol_bits(i, 0), reverse_bits(i)) << i;
}

// A sample's point is the same whether its set's keys come from the pixel's cache or are made
// for it alone (sets beyond the cache): set 40 of a pixel, reached the long way, against a
// pixel whose cache holds it (made after its first 32 sets were skipped: the same function).
TEST(PathSamplerTest, SetsBeyondTheCacheAreTheSameFunction) {
  static_assert(PaddedPixel::k_cached_sets < 40);
  for (PathSampler kind : {PathSampler::jittered, PathSampler::sobol})
    for (std::uint32_t s = 0; s < 8; ++s) {
      PaddedPixel pixel(kind, 5, 8);
      PaddedSample sample(pixel, s);
      for (unsigned k = 0; k < 40; ++k) sample.uniform2();
      const Vec2 long_way = sample.uniform2();  // set 40
      PaddedPixel other(kind, 5, 8);
      EXPECT_EQ(other.point(s, 40), long_way) << name_of(kind) << " sample " << s;
      // and a cached set against the keys made directly
      const PaddedSetKeys direct = padded_set_keys(kind, 5, 3);
      const PaddedSetKeys& cached = other.set(3);
      EXPECT_EQ(direct.key, cached.key);
      EXPECT_EQ(direct.seed_x, cached.seed_x);
      EXPECT_EQ(direct.round_b[2], cached.round_b[2]);
    }
}

// Padding: each bounce's set is scrambled by a key of its own, so two bounces (and the pixel
// position) never repeat one another's points. Without padding (one scramble for every set),
// a path's directions would be the same point at every bounce.
TEST(PathSamplerTest, EachBounceHasItsOwnScramble) {
  for (PathSampler kind : {PathSampler::jittered, PathSampler::sobol})
    for (std::uint64_t key : {1ull, 7ull})
      for (unsigned a = 0; a < 5; ++a)
        for (unsigned b = a + 1; b < 6; ++b) {
          EXPECT_NE(padded_set_key(key, a), padded_set_key(key, b));
          const std::vector<Vec2> pa = set_points(kind, key, 16, a);
          const std::vector<Vec2> pb = set_points(kind, key, 16, b);
          int same = 0;
          for (std::size_t s = 0; s < pa.size(); ++s) same += pa[s] == pb[s];
          EXPECT_EQ(same, 0) << name_of(kind) << " sets " << a << " and " << b;
        }
}

TEST(PathSamplerTest, ShuffledSampleIsAPermutation) {
  for (std::uint32_t n = 1; n <= 70; ++n)
    for (std::uint64_t key : {0ull, 3ull, 1234567ull}) {
      std::vector<int> hits(n, 0);
      const PaddedSetKeys keys = padded_set_keys(PathSampler::sobol, key, 1);
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = n <= 1 ? 0 : shuffled_sample(i, n, shuffle_half_bits(n), keys);
        ASSERT_LT(j, n);
        ++hits[j];
      }
      for (int h : hits) EXPECT_EQ(h, 1) << "n " << n;
    }
}

// Padding pairs two sets at random. Owen scrambling keeps the nesting of the sample order, so
// without a permutation of the samples per set, the first binary digits of bounce 0's and
// bounce 1's x would agree for all 16 samples of a pixel or for none, at every key. With it,
// the number that agree is hypergeometric (8 of 16 on average; all or none with probability
// 2 / C(16, 8) = 1.6e-4): over 200 keys, 3 or more such keys has probability below 1e-6.
TEST(PathSamplerTest, PaddedSetsArePairedAtRandom) {
  for (PathSampler kind : {PathSampler::jittered, PathSampler::sobol}) {
    int all_or_none = 0;
    for (std::uint64_t key = 0; key < 200; ++key) {
      const std::vector<Vec2> a = set_points(kind, key, 16, 1), b = set_points(kind, key, 16, 2);
      int agree = 0;
      for (std::size_t s = 0; s < a.size(); ++s) agree += (a[s].x < 0.5) == (b[s].x < 0.5);
      all_or_none += agree == 0 || agree == 16;
    }
    EXPECT_LE(all_or_none, 2) << name_of(kind);
  }
}

// Two renders of the same pixel with different first samples (chapter 05's A and B) are
// randomised independently: their keys, and so their points, differ.
TEST(PathSamplerTest, PixelsAndSampleBlocksHaveTheirOwnKeys) {
  EXPECT_NE(PaddedPixel::pixel_key(1, 0, 0), PaddedPixel::pixel_key(1, 1, 0));
  EXPECT_NE(PaddedPixel::pixel_key(1, 0, 0), PaddedPixel::pixel_key(1, 0, 16));
  EXPECT_NE(PaddedPixel::pixel_key(1, 0, 0), PaddedPixel::pixel_key(2, 0, 0));
  EXPECT_NE(set_points(PathSampler::sobol, PaddedPixel::pixel_key(1, 0, 0), 16, 1),
            set_points(PathSampler::sobol, PaddedPixel::pixel_key(1, 0, 16), 16, 1));
}

// A sample is a pure function of (key, count, index) and how many sets came before: made again,
// in another order, it is the same bits. uniform() takes a whole set (its first coordinate).
TEST(PathSamplerTest, SamplesArePureFunctionsOfTheirAddress) {
  for (PathSampler kind : {PathSampler::jittered, PathSampler::sobol}) {
    PaddedPixel pixel(kind, 99, 8), fresh(kind, 99, 8);
    PaddedSample first(pixel, 5), again(fresh, 5);
    const Vec2 p0 = first.uniform2();
    const double u1 = first.uniform();
    const Vec2 p2 = first.uniform2();
    EXPECT_EQ(first.sets_drawn(), 3u);
    EXPECT_EQ(again.uniform2(), p0);
    EXPECT_EQ(again.uniform2().x, u1);
    EXPECT_EQ(again.uniform2(), p2);
  }
}

}  // namespace
