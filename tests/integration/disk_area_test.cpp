// Hit-or-miss estimators, deterministic properties: exact ball volumes, the theory formulas,
// the generator lanes against pcg-cpp, the lecture's loop against the 16-lane engine behind
// it, the AVX2 path against the portable one, thread-count independence. And the statistical procedures of tests/checks must reject known-wrong
// estimators (a test that cannot fail is no test).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <pcg_random.hpp>

#include "core/pcg32_lanes.hpp"
#include "integration/ball.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"
#include "integration/disk_area_known_bugs.hpp"
#include "integration/disk_area_procedures.hpp"

using namespace mcrt;

namespace {

TEST(BallVolumeTest, MatchesTheClosedFormsForKFrom0To12) {
  const double pi = k_pi;
  // V_2m = pi^m / m!,  V_2m+1 = 2^(m+1) pi^m / (2m+1)!!.
  const double expected[] = {1.0,
                             2.0,
                             pi,
                             4.0 * pi / 3.0,
                             pi * pi / 2.0,
                             8.0 * pi * pi / 15.0,
                             pi * pi * pi / 6.0,
                             16.0 * pi * pi * pi / 105.0,
                             std::pow(pi, 4) / 24.0,
                             32.0 * std::pow(pi, 4) / 945.0,
                             std::pow(pi, 5) / 120.0,
                             64.0 * std::pow(pi, 5) / 10395.0,
                             std::pow(pi, 6) / 720.0};
  for (int k = 0; k <= 12; ++k)
    // pow and tgamma are each within a few ulps: 1e-13 relative leaves room, and a wrong
    // formula (Gamma(k/2) instead of Gamma(k/2 + 1)) is off by a factor k/2.
    EXPECT_NEAR(unit_ball_volume(k), expected[k], 1e-13 * expected[k]) << "k = " << k;
  // The volume peaks at k = 5 and then falls towards 0.
  EXPECT_GT(unit_ball_volume(5), unit_ball_volume(4));
  EXPECT_GT(unit_ball_volume(5), unit_ball_volume(6));
}

TEST(HitOrMissTheoryTest, BernoulliMomentsAndStandardDeviations) {
  const double p = k_disk_hit_probability;
  EXPECT_DOUBLE_EQ(p, k_pi / 4.0);
  EXPECT_DOUBLE_EQ(hit_count_mean(1000, p), 1000.0 * p);
  EXPECT_DOUBLE_EQ(hit_count_variance(1000, p), 1000.0 * p * (1.0 - p));
  // 4 sqrt(p (1 - p) / N) = 1.6421834 / sqrt(N) (the constant to the 7 digits given).
  EXPECT_NEAR(disk_area_theory_std(1), 1.6421834, 1e-7);
  EXPECT_DOUBLE_EQ(disk_area_theory_std(100), disk_area_theory_std(1) / 10.0);
  // V[4 M / N] = 16 V[M] / N^2.
  EXPECT_DOUBLE_EQ(disk_area_theory_std(250) * disk_area_theory_std(250),
                   16.0 * hit_count_variance(250, p) / (250.0 * 250.0));
  EXPECT_DOUBLE_EQ(ball_hit_probability(2), p);
  EXPECT_DOUBLE_EQ(ball_volume_theory_std(2, 400), disk_area_theory_std(400));
  EXPECT_DOUBLE_EQ(ball_hit_probability(1), 1.0);  // the segment fills its cube
  EXPECT_EQ(ball_volume_theory_std(1, 10), 0.0);  // every point of [-1, 1) is inside
  EXPECT_DOUBLE_EQ(ball_hit_probability(3), k_pi / 6.0);
  // The relative std sqrt((1 - q) / (q N)) grows with k.
  for (int k = 2; k < 12; ++k)
    EXPECT_GT(ball_volume_theory_std(k + 1, 1000) / unit_ball_volume(k + 1),
              ball_volume_theory_std(k, 1000) / unit_ball_volume(k));
}

TEST(Pcg32LanesTest, EachLaneIsTheLibrarysPcg32) {
  Pcg32Lanes<4> lanes;
  for (int l = 0; l < 4; ++l) lanes.seed_lane(l, 42 + l, 1000 * l + 7);
  for (int l = 0; l < 4; ++l) {
    pcg32 reference(42 + l, 1000 * l + 7);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(lanes.next(l), reference()) << "lane " << l;
  }
}

TEST(Pcg32LanesTest, SeededFromAnRngDrawsSeedAndStreamPerLane) {
  Rng rng(5, 6), copy(5, 6);
  Pcg32Lanes<16> lanes;
  lanes.seed_from(rng);
  for (int l = 0; l < 16; ++l) {
    const std::uint64_t seed = (std::uint64_t{copy.next_bits()} << 32) | copy.next_bits();
    const std::uint64_t stream = (std::uint64_t{copy.next_bits()} << 32) | copy.next_bits();
    pcg32 reference(seed, stream);
    for (int i = 0; i < 10; ++i) ASSERT_EQ(lanes.next(l), reference()) << "lane " << l;
  }
}

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

TEST(BallEstimatorTest, DegenerateDimensionsAreExact) {
  Rng rng(1, 2);
  EXPECT_EQ(estimate_ball_volume(0, 100, rng), 1.0);  // the 0-ball is the whole 0-cube
  EXPECT_EQ(estimate_ball_volume(1, 100, rng), 2.0);  // [-1, 1) lies in [-1, 1]
  EXPECT_EQ(count_in_ball(2, 0, rng), 0u);
  EXPECT_THROW(count_in_ball(-1, 10, rng), std::invalid_argument);
  EXPECT_THROW(count_in_ball(k_max_ball_dims + 1, 10, rng), std::invalid_argument);
  EXPECT_NO_THROW(count_in_ball(k_max_ball_dims, 10, rng));
}

TEST(BallEstimatorTest, SameStreamSameEstimate) {
  Rng a(7, 8), b(7, 8);
  EXPECT_EQ(estimate_ball_volume(5, 1000, a), estimate_ball_volume(5, 1000, b));
}

// --- The checks' procedures reject known-wrong estimators (at the same alpha = 1e-4). ---

constexpr double k_alpha = 1e-4;

TEST(DiskAreaProceduresTest, RejectKnownWrongEstimators) {
  const std::uint64_t seed = 20261122;
  EXPECT_LT(mcrt::testing::pooled_mean_p_value(mcrt::testing::disk_area_same_coordinate_twice, k_pi, disk_area_theory_std, 1,
                                        seed, 0),
            k_alpha);
  EXPECT_LT(mcrt::testing::variance_p_value(mcrt::testing::disk_area_identical_lanes, 4.0, k_disk_hit_probability, 1024, 1000,
                                     seed, 1),
            k_alpha);
  EXPECT_LT(mcrt::testing::error_slope(mcrt::testing::disk_area_biased, k_pi, 10, 100000, 50, seed, 2).p_value, k_alpha);
  EXPECT_LT(mcrt::testing::pooled_mean_p_value(
                mcrt::testing::ball_volume_half_scale, unit_ball_volume(3),
                [](std::uint64_t n) { return ball_volume_theory_std(3, n); }, 1, seed, 3),
            k_alpha);
}

TEST(DiskAreaProceduresTest, AcceptTheRightEstimatorAtSmallSizes) {
  // The same procedures, smaller, on the lecture's loop (another seed than the checks, which
  // run the chapter's engine): each passes with probability 1 - 1e-4.
  const std::uint64_t seed = 77;
  EXPECT_GE(mcrt::testing::variance_p_value(estimate_disk_area, 4.0, k_disk_hit_probability, 64, 2000,
                                     seed, 4),
            k_alpha);
  const auto slope = mcrt::testing::error_slope(estimate_disk_area, k_pi, 10, 10000, 50, seed, 5);
  EXPECT_GE(slope.p_value, k_alpha) << "slope " << slope.slope << " +- " << slope.standard_error;
}

}  // namespace
