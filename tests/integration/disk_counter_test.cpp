// The disk engine (integration/disk_counter.hpp): its points are the documented lattice with
// an exact inside test; the AVX2 and portable paths and the lecture's loop count the same M
// from the same stream; the parallel count is the sum of its chunks whatever the threads.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <pcg_random.hpp>

#include "core/pcg32_lanes.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"

using namespace mcrt;

namespace {

// The documented layout, written the plain way: point i is (x, y) from lane i mod 16, where
// lane l is pcg32 seeded from the Rng; inside iff x^2 + y^2 <= 1 for x = int32 / 2^31. The
// product of two 32-bit values and their sum are exact in long double's 64-bit mantissa.
std::uint64_t reference_count(std::uint64_t n, Rng& rng) {
  std::vector<pcg32> lanes;
  for (int l = 0; l < 16; ++l) {
    const std::uint64_t seed = (std::uint64_t{rng.next_bits()} << 32) | rng.next_bits();
    const std::uint64_t stream = (std::uint64_t{rng.next_bits()} << 32) | rng.next_bits();
    lanes.emplace_back(seed, stream);
  }
  std::uint64_t inside = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    pcg32& lane = lanes[i % 16];
    const long double x = static_cast<std::int32_t>(lane()) * 0x1p-31L;
    const long double y = static_cast<std::int32_t>(lane()) * 0x1p-31L;
    inside += x * x + y * y <= 1.0L;
  }
  return inside;
}

TEST(CountInDiskTest, FastAndPortablePathsEqualThePlainReference) {
  RecordProperty("avx2", disk_count_uses_avx2() ? "yes" : "no");
  for (std::uint64_t n : {0, 1, 15, 16, 17, 33, 1000, 100003}) {
    Rng fast(11, n), portable(11, n), reference(11, n);
    const std::uint64_t m = count_in_disk(n, fast);
    EXPECT_EQ(m, count_in_disk_portable(n, portable)) << "n = " << n;
    EXPECT_EQ(m, reference_count(n, reference)) << "n = " << n;
    EXPECT_EQ(fast.next_bits(), reference.next_bits());  // both took the same 64 draws
    EXPECT_LE(m, n);
  }
}

TEST(DiskPointsTest, CoordinatesAreTheLatticeAndTheInsideTestIsExact) {
  constexpr std::int32_t k_min = -2147483647 - 1;  // -2^31: x = -1
  EXPECT_EQ((DiskPoint{k_min, 0}.x()), -1.0);
  EXPECT_EQ((DiskPoint{0, 1 << 30}.y()), 0.5);
  EXPECT_TRUE(inside_unit_disk({0, 0}));
  // The only lattice points on the circle are (-1, 0) and (0, -1) (2^62 is a sum of two
  // squares only as 2^62 + 0); x^2 + y^2 <= 1 counts them in.
  EXPECT_TRUE(inside_unit_disk({k_min, 0}));
  EXPECT_TRUE(inside_unit_disk({0, k_min}));
  EXPECT_FALSE(inside_unit_disk({k_min, 1}));
  // On the diagonal, 2 i^2 = 2^62 - 6.0e9 is inside and 2 (i + 1)^2 = 2^62 + 7.3e7 is not: a
  // double's x^2 + y^2 could not tell them apart reliably, the integer test can.
  EXPECT_TRUE(inside_unit_disk({1518500249, 1518500249}));
  EXPECT_FALSE(inside_unit_disk({1518500250, 1518500250}));
  EXPECT_FALSE(inside_unit_disk({1518500250, -1518500250}));
}

// The lecture's loop (estimate_disk_area) and the engine (count_in_disk) from the same stream:
// the same M, so the same 4 M / N, and the same generator state afterwards.
TEST(CountInDiskTest, EngineCountsWhatTheLecturesLoopCounts) {
  std::vector<std::uint64_t> sizes;
  for (std::uint64_t n = 0; n <= 64; ++n) sizes.push_back(n);
  for (std::uint64_t n : {1000, 4099, 65536, 1000003}) sizes.push_back(n);
  for (std::uint64_t seed : {1, 2, 20261122}) {
    for (std::uint64_t n : sizes) {
      Rng plain(seed, n), engine(seed, n), portable(seed, n);
      const double area = estimate_disk_area(n, plain);
      const std::uint64_t m = count_in_disk(n, engine);
      EXPECT_EQ(count_in_disk_portable(n, portable), m) << "seed " << seed << ", n = " << n;
      const double expected = 4.0 * static_cast<double>(m) / static_cast<double>(n);
      if (n == 0)
        EXPECT_TRUE(std::isnan(area));  // 0 / 0: the loop needs a point
      else
        EXPECT_EQ(area, expected) << "seed " << seed << ", n = " << n;
      // Both drew their 16 lanes' seeds (64 numbers) and nothing else from the stream.
      const std::uint32_t after = plain.next_bits();
      EXPECT_EQ(engine.next_bits(), after) << "seed " << seed << ", n = " << n;
      EXPECT_EQ(portable.next_bits(), after) << "seed " << seed << ", n = " << n;
    }
  }
  Rng plain(3, 4), fast(3, 4);
  EXPECT_EQ(estimate_disk_area(12345, plain), estimate_disk_area_fast(12345, fast));
}

TEST(CountInDiskTest, ParallelCountIsTheSumOfItsChunksWhateverTheThreads) {
  const std::uint64_t n = 2 * k_disk_chunk + 12345;
  std::uint64_t by_hand = 0;
  for (std::uint64_t j = 0; j < 3; ++j) {
    Rng rng(3, stream_index(9, j));
    by_hand += count_in_disk(j < 2 ? k_disk_chunk : 12345, rng);
  }
  EXPECT_EQ(count_in_disk_parallel(n, 3, 9, 1), by_hand);
  EXPECT_EQ(count_in_disk_parallel(n, 3, 9, 2), by_hand);
  EXPECT_EQ(count_in_disk_parallel(n, 3, 9, 5), by_hand);
  EXPECT_NE(count_in_disk_parallel(n, 4, 9, 2), by_hand);  // another seed, other points
}

}  // namespace
