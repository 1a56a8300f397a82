#pragma once
// Known-wrong hit-or-miss estimators, kept so tests/integration/disk_area_test.cpp can show that the
// disk-area checks' procedures reject them (and tests/assignments/diagnosis_test.cpp that a1's
// grading names them).

#include <cmath>
#include <cstdint>

#include "core/rng.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"

namespace mcrt::testing {

/// Wrong: y drawn equal to x, so the test is 2 x^2 <= 1 and the estimate is 4/sqrt(2) = 2.83.
inline double disk_area_same_coordinate_twice(std::uint64_t n, Rng& rng) {
  std::uint64_t inside = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double x = 2.0 * rng.uniform() - 1.0;
    inside += 2.0 * x * x <= 1.0;
  }
  return 4.0 * static_cast<double>(inside) / static_cast<double>(n);
}

/// Wrong: all 16 lanes seeded alike, every point repeated 16 times: unbiased, 16x the variance.
inline double disk_area_identical_lanes(std::uint64_t n, Rng& rng) {
  return 4.0 * static_cast<double>(count_in_disk(n / 16, rng)) / static_cast<double>(n / 16);
}

/// Wrong: a fixed bias of 0.02, so the rms error stops falling once sigma is below it.
inline double disk_area_biased(std::uint64_t n, Rng& rng) {
  return estimate_disk_area(n, rng) + 0.02;
}

/// Wrong: the 3-ball's estimate scaled by 2^(k-1) instead of 2^k.
inline double ball_volume_half_scale(std::uint64_t n, Rng& rng) {
  return estimate_ball_volume(3, n, rng) / 2;
}

/// Wrong, not Monte Carlo: no random number drawn, the multiple of 4/N nearest pi (unbiased
/// to within 2/N, zero spread).
inline double disk_area_nearest_multiple_of_four_over_n(std::uint64_t n, Rng&) {
  const auto count = static_cast<double>(n);
  return 4.0 * std::round(count * k_pi / 4.0) / count;
}

/// Wrong: 4N points drawn where N were asked: unbiased, a quarter of the variance.
inline double disk_area_four_times_the_points(std::uint64_t n, Rng& rng) {
  return estimate_disk_area(4 * n, rng);
}

/// Wrong, not Monte Carlo: the expected count N p (rounded) in place of the count M, so
/// 2^k round(N p) / N with p = V_k / 2^k: no random number drawn, zero spread.
inline double ball_volume_expected_count(int k, std::uint64_t n, Rng&) {
  return std::ldexp(std::round(hit_count_mean(n, ball_hit_probability(k))), k) /
         static_cast<double>(n);
}

}  // namespace mcrt::testing
