// Hit-or-miss estimators (integration/disk_area.hpp), deterministic properties: the theory
// formulas, the k-ball estimator's exact cases and streams; and the statistical procedures of
// the checks must reject known-wrong estimators (a test that cannot fail is no test). (The
// disk engine behind estimate_disk_area: tests/integration/disk_counter_test.cpp; the lanes:
// tests/core/pcg32_lanes_test.cpp; the ball's volume: tests/integration/ball_test.cpp.)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "integration/ball.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_area_known_bugs.hpp"
#include "integration/disk_area_procedures.hpp"

using namespace mcrt;

namespace {

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
  EXPECT_EQ(ball_volume_theory_std(1, 10), 0.0);   // every point of [-1, 1) is inside
  EXPECT_DOUBLE_EQ(ball_hit_probability(3), k_pi / 6.0);
  // The relative std sqrt((1 - q) / (q N)) grows with k.
  for (int k = 2; k < 12; ++k)
    EXPECT_GT(ball_volume_theory_std(k + 1, 1000) / unit_ball_volume(k + 1),
              ball_volume_theory_std(k, 1000) / unit_ball_volume(k));
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
  EXPECT_LT(mcrt::testing::pooled_mean_p_value(mcrt::testing::disk_area_same_coordinate_twice, k_pi,
                                               disk_area_theory_std, 1, seed, 0),
            k_alpha);
  EXPECT_LT(mcrt::testing::variance_p_value(mcrt::testing::disk_area_identical_lanes, 4.0,
                                            k_disk_hit_probability, 1024, 1000, seed, 1),
            k_alpha);
  EXPECT_LT(mcrt::testing::error_slope(mcrt::testing::disk_area_biased, k_pi, 10, 100000, 50, seed,
                                       2)
                .p_value,
            k_alpha);
  EXPECT_LT(mcrt::testing::pooled_mean_p_value(
                mcrt::testing::ball_volume_half_scale, unit_ball_volume(3),
                [](std::uint64_t n) { return ball_volume_theory_std(3, n); }, 1, seed, 3),
            k_alpha);
}

TEST(DiskAreaProceduresTest, AcceptTheRightEstimatorAtSmallSizes) {
  // The same procedures, smaller, on the lecture's loop (another seed than the checks, which
  // run the chapter's engine): each passes with probability 1 - 1e-4.
  const std::uint64_t seed = 77;
  EXPECT_GE(mcrt::testing::variance_p_value(estimate_disk_area, 4.0, k_disk_hit_probability, 64,
                                            2000, seed, 4),
            k_alpha);
  const auto slope = mcrt::testing::error_slope(estimate_disk_area, k_pi, 10, 10000, 50, seed, 5);
  EXPECT_GE(slope.p_value, k_alpha) << "slope " << slope.slope << " +- " << slope.standard_error;
}

}  // namespace
