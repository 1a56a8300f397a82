// Generator streams: reproducible, distinct, in range. (Their distribution is checked by the
// statistical checks in tests/core/rng_checks.cpp.)

#include <algorithm>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "integration/log_grid.hpp"

using namespace mcrt;

namespace {

TEST(RngTest, SameSeedAndStreamGiveTheSameSequence) {
  Rng a(42, 7), b(42, 7);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_bits(), b.next_bits());
}

TEST(RngTest, DifferentStreamsOrSeedsGiveDifferentSequences) {
  std::set<std::uint32_t> firsts;
  for (std::uint64_t stream = 0; stream < 100; ++stream) {
    Rng rng(42, stream);
    firsts.insert(rng.next_bits());
  }
  EXPECT_EQ(firsts.size(), 100u);  // 32-bit collisions among 100 values: chance ~1e-6
  Rng a(1, 0), b(2, 0);
  int equal = 0;
  for (int i = 0; i < 100; ++i) equal += a.next_bits() == b.next_bits();
  EXPECT_LT(equal, 2);
}

TEST(RngTest, UniformIsInTheHalfOpenUnitInterval) {
  Rng rng(3, 3);
  for (int i = 0; i < 100000; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  for (int i = 0; i < 1000; ++i) ASSERT_LT(rng.uniform_below(7), 7u);
}

TEST(RngTest, StreamIndexSeparatesPairs) {
  EXPECT_NE(stream_index(1, 0), stream_index(0, 1));
  EXPECT_NE(stream_index(5, 3), stream_index(3, 5));
}

TEST(ParallelTest, EveryIndexRunsOnceWhateverTheThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<int> runs(1000, 0);
    parallel_for(runs.size(), threads, [&](std::size_t i) { runs[i] += 1; });
    for (int r : runs) ASSERT_EQ(r, 1);
  }
}

TEST(ParallelTest, ExceptionsReachTheCaller) {
  EXPECT_THROW(parallel_for(100, 2,
                            [](std::size_t i) {
                              if (i == 37) throw std::runtime_error("boom");
                            }),
               std::runtime_error);
}

TEST(LogGridTest, CoversTheRangeEvenlyInLog) {
  const auto grid = log_grid(10, 100000, 4);
  EXPECT_EQ(grid.front(), 10u);
  EXPECT_EQ(grid.back(), 100000u);
  EXPECT_EQ(grid.size(), 17u);  // 4 decades x 4 per decade + 1
  for (std::size_t i = 1; i < grid.size(); ++i) EXPECT_GT(grid[i], grid[i - 1]);
  EXPECT_EQ(log_grid(5, 5, 4), std::vector<std::uint64_t>{5});
}

// stream_key is the mixed-radix number of its parts, most significant first.
TEST(StreamKeyTest, EqualsTheMixedRadixFormula) {
  EXPECT_EQ(stream_key({}), 0u);
  EXPECT_EQ(stream_key({{7, 10}}), 7u);
  EXPECT_EQ(stream_key({{3, 4}, {5, 6}}), 3u * 6u + 5u);
  EXPECT_EQ(stream_key({{2, 4}, {9, 10}, {99, 100}}), (2u * 10u + 9u) * 100u + 99u);
  // The hand-packed ids it replaced: (part << 24 | index) << 32 ^ trial, 256 k + i, study 1000 + i.
  const std::uint64_t part = 200, index = (1u << 24) - 1, trial = 0xdeadbeef;
  EXPECT_EQ(stream_key({{part, 256}, {index, 1u << 24}, {trial, 1ull << 32}}),
            ((part << 24 | index) << 32) ^ trial);
  EXPECT_EQ(stream_key({{3, 1000}, {255, 256}}), 256u * 3u + 255u);
  EXPECT_EQ(stream_key({{12, 100}, {999, 1000}}), 12u * 1000u + 999u);
  // The first part may use all the room the others leave: the largest key is 2^64 - 1.
  EXPECT_EQ(stream_key({{(1ull << 32) - 1, 1ull << 32}, {(1ull << 32) - 1, 1ull << 32}}),
            ~std::uint64_t{0});
}

TEST(StreamKeyTest, ReproducesStreamIndexBelowTwoToThe32) {
  Rng rng(5, 0);
  const std::uint64_t edges[] = {0, 1, 255, 1ull << 31, (1ull << 32) - 1};
  std::vector<std::uint64_t> values(std::begin(edges), std::end(edges));
  for (int i = 0; i < 50; ++i) values.push_back(rng.next_bits());  // 32-bit draws
  for (std::uint64_t a : values)
    for (std::uint64_t b : values)
      ASSERT_EQ(stream_key({{a, 1ull << 32}, {b, 1ull << 32}}), stream_index(a, b))
          << a << " " << b;
}

TEST(StreamKeyTest, ThrowsOnAPartOutOfItsRange) {
  EXPECT_THROW(static_cast<void>(stream_key({{10, 10}})), std::out_of_range);
  EXPECT_THROW(static_cast<void>(stream_key({{1, 4}, {6, 6}})), std::out_of_range);
  EXPECT_THROW(static_cast<void>(stream_key({{0, 0}})), std::out_of_range);
}

TEST(StreamKeyTest, ThrowsWhenTheKeyNeedsMoreThan64Bits) {
  EXPECT_THROW(static_cast<void>(stream_key({{1, 2}, {0, 1ull << 32}, {0, 1ull << 32}})),
               std::out_of_range);
  EXPECT_THROW(static_cast<void>(stream_key({{1ull << 32, 1ull << 33}, {0, 1ull << 32}})),
               std::out_of_range);
  // The first part may be anything that keeps the key within 64 bits.
  EXPECT_NO_THROW(static_cast<void>(stream_key({{1, 3}, {0, 1ull << 63}})));
}

// Known gap of common/core/rng.hpp: the check tests key * count against 2^64 - 1 but not the
// value added after it, so (2^64 - 1) / 3 * 3 + 2 = 2^64 + 1 wraps to 1 unnoticed. Enable
// once stream_key checks key * count + value.
TEST(StreamKeyTest, ThrowsWhenAddingTheLastValueOverflows) {
  EXPECT_THROW(static_cast<void>(stream_key({{6148914691236517205u, 1ull << 63}, {2, 3}})),
               std::out_of_range);
}

// Stream collisions, as properties rather than a two-pair assertion: the keys of every
// (pixel, sample) pair of a 64 x 64 image at 64 samples (262 144 pairs, the render loop's
// keying) are all distinct, and so are the generators they give (the first 64 bits drawn:
// a collision among 2^18 random 64-bit words has chance 2^-29). Random pairs anywhere below
// 2^32 round-trip through the key's two halves, so distinct pairs can never share a stream.
TEST(StreamIndexTest, EveryPixelSamplePairGetsItsOwnStream) {
  std::vector<std::uint64_t> keys, firsts;
  for (std::uint64_t pixel = 0; pixel < 64 * 64; ++pixel)
    for (std::uint64_t sample = 0; sample < 64; ++sample) {
      keys.push_back(stream_index(pixel, sample));
      Rng rng(1, keys.back());
      const std::uint64_t high = rng.next_bits();
      firsts.push_back(high << 32 | rng.next_bits());
    }
  for (auto* v : {&keys, &firsts}) {
    std::sort(v->begin(), v->end());
    EXPECT_EQ(std::adjacent_find(v->begin(), v->end()), v->end());
  }
  Rng rng(6, 0);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t a = rng.next_bits(), b = rng.next_bits();
    const std::uint64_t key = stream_index(a, b);
    ASSERT_EQ(key >> 32, a);
    ASSERT_EQ(key & 0xffffffffu, b);
  }
}

// stream_key is a bijection of its mixed-radix digits: random keys of three parts decode
// back to their parts, so distinct parts never collide.
TEST(StreamKeyTest, RandomKeysDecodeToTheirParts) {
  Rng rng(7, 0);
  for (int i = 0; i < 100000; ++i) {
    const std::uint64_t count_b = 1 + rng.uniform_below(1u << 20), count_c = 1 + rng.next_bits();
    const std::uint64_t a = rng.uniform_below(1u << 10), b = rng.next_bits() % count_b,
                        c = rng.next_bits() % count_c;
    const std::uint64_t key = stream_key({{a, 1u << 10}, {b, count_b}, {c, count_c}});
    ASSERT_EQ(key % count_c, c);
    ASSERT_EQ(key / count_c % count_b, b);
    ASSERT_EQ(key / count_c / count_b, a);
  }
}

}  // namespace
