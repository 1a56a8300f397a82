// Hit-or-miss estimators of chapter 02 against their closed forms: the disk estimate 4 M / N
// (the 16-lane engine the chapter runs, integration/disk_counter.hpp, which counts what the
// lecture's loop counts) has mean pi, variance 16 p (1 - p) / N and an rms error falling as
// N^-1/2; the k-ball estimate 2^k M / N has mean V_k. Each check has
// false-failure rate 1e-4 (its alpha).

#include <cstdint>

#include "integration/disk_area_procedures.hpp"
#include "core/math.hpp"
#include "integration/ball.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"
#include "stats/check.hpp"

namespace {

constexpr double k_alpha = 1e-4;

// Stream families, one per check, so no two checks share random numbers.
constexpr std::uint64_t k_mean_streams = 0x0200'0000;
constexpr std::uint64_t k_variance_stream = 0x0201'0000;
constexpr std::uint64_t k_slope_streams = 0x0202'0000;
constexpr std::uint64_t k_ball_streams = 0x0203'0000;

// Pooled over 10 sizes x 3 trials, 1.6e7 points in all: the z-test's standard error is
// 4 e-4, so a bias above ~2e-3 is found.
MCRT_STATISTICAL_CHECK(disk_area_mean_is_pi, k_alpha) {
  return mcrt::testing::pooled_mean_p_value(mcrt::estimate_disk_area_fast, mcrt::k_pi,
                                            mcrt::disk_area_theory_std, 3, seed, k_mean_streams);
}

// 4000 estimates at N = 1000 (not a multiple of the 16 lanes): s^2 has a relative standard
// error of sqrt(2 / 4000) = 2.2 %, so a variance off by 10 % is found.
MCRT_STATISTICAL_CHECK(disk_area_variance_is_16pq_over_n, k_alpha) {
  return mcrt::testing::variance_p_value(mcrt::estimate_disk_area_fast, 4.0,
                                         mcrt::k_disk_hit_probability, 1000, 4000, seed,
                                         k_variance_stream);
}

// 200 trials at each N of a 4-per-decade grid from 10 to 10^5 (17 sizes, 4.6e7 points).
MCRT_STATISTICAL_CHECK(disk_area_error_slope_is_minus_one_half, k_alpha) {
  return mcrt::testing::error_slope(mcrt::estimate_disk_area_fast, mcrt::k_pi, 10, 100000, 200,
                                    seed, k_slope_streams)
      .p_value;
}

// The k-ball estimate pooled over the 10 sizes, one trial each (5.3e6 points): relative
// standard errors 4e-4 (k = 3, q = 0.52) and 2.2e-3 (k = 7, q = 0.037).
double ball_mean_p_value(int k, std::uint64_t seed) {
  return mcrt::testing::pooled_mean_p_value(
      [k](std::uint64_t n, mcrt::Rng& rng) { return mcrt::estimate_ball_volume(k, n, rng); },
      mcrt::unit_ball_volume(k),
      [k](std::uint64_t n) { return mcrt::ball_volume_theory_std(k, n); }, 1, seed,
      k_ball_streams + 0x100 * static_cast<std::uint64_t>(k));
}

MCRT_STATISTICAL_CHECK(ball_volume_k3_is_unbiased, k_alpha) { return ball_mean_p_value(3, seed); }

MCRT_STATISTICAL_CHECK(ball_volume_k7_is_unbiased, k_alpha) { return ball_mean_p_value(7, seed); }

}  // namespace
