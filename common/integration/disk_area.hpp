#pragma once
/// Hit-or-miss Monte Carlo: the area of the unit disk and the volume of the unit k-ball.
///
/// Draw N points X_i uniformly in the cube [-1,1]^k, count the M that land in the ball.
/// Each point is a Bernoulli variable with success probability p = V_k / 2^k (p = pi/4 in 2D),
/// so M is Binomial(N, p) and
///   E[M] = N p,              V[M] = N p (1 - p),
///   E[2^k M / N] = V_k,      V[2^k M / N] = 4^k p (1 - p) / N,
/// an unbiased estimate whose standard deviation falls as N^-1/2 in every dimension, with a
/// constant sqrt((1 - p) / p) (relative) that grows quickly with k as the ball fills less of
/// the cube.
///
/// The disk's points are lattice points: a coordinate is a 32-bit integer j / 2^31, j in
/// [-2^31, 2^31). The lattice's hit fraction differs from p by the lattice-point error of the
/// disk, about 1e-12 relative: no experiment of fewer than 1e20 points can see it.

#include <cstdint>

#include "core/math.hpp"
#include "core/pcg32_lanes.hpp"
#include "core/rng.hpp"

namespace mcrt {

/// p = pi / 4: the probability that a uniform point of [-1,1]^2 lands in the unit disk.
inline constexpr double k_disk_hit_probability = k_pi / 4.0;

/// The largest dimension the k-ball estimator accepts (its point lives on the stack).
inline constexpr int k_max_ball_dims = 100;

/// p = V_k / 2^k: the probability that a uniform point of [-1,1]^k lands in the unit k-ball.
double ball_hit_probability(int k);

/// E[M] = N p for M hits among N points.
double hit_count_mean(std::uint64_t n, double p);
/// V[M] = N p (1 - p).
double hit_count_variance(std::uint64_t n, double p);
/// Standard deviation of the estimate |box| M / N: |box| sqrt(p (1 - p) / N).
double hit_or_miss_std(double box_volume, double p, std::uint64_t n);

/// Theory standard deviation of the disk estimate 4 M / N: 4 sqrt(p (1 - p) / N), p = pi/4.
double disk_area_theory_std(std::uint64_t n);
/// Theory standard deviation of the k-ball estimate: 2^k sqrt(q (1 - q) / N), q = V_k / 2^k.
double ball_volume_theory_std(int k, std::uint64_t n);

/// A point of [-1, 1)^2 on the lattice of spacing 2^-31: x = i / 2^31, y = j / 2^31.
struct DiskPoint {
  std::int32_t i = 0, j = 0;
  double x() const { return i * 0x1p-31; }
  double y() const { return j * 0x1p-31; }
};

/// x^2 + y^2 <= 1, exactly: i^2 + j^2 <= 2^62 in 64-bit integers (each square is at most
/// 2^62, so the sum, at most 2^63, fits).
constexpr bool inside_unit_disk(DiskPoint p) {
  const std::int64_t i = p.i, j = p.j;
  return static_cast<std::uint64_t>(i * i) + static_cast<std::uint64_t>(j * j) <=
         (std::uint64_t{1} << 62);
}

/// Uniform points of [-1, 1)^2, from 16 PCG32 lanes seeded from `rng` (64 draws): point i
/// comes from lane i mod 16, x and then y from that lane's next two 32-bit outputs read as
/// signed integers. The lanes let the fast counter (integration/disk_counter.hpp) draw the
/// very same points 16 at a time.
class DiskPoints {
 public:
  static constexpr int k_lanes = 16;
  using Lanes = Pcg32Lanes<k_lanes>;

  explicit DiskPoints(Rng& rng) { lanes_.seed_from(rng); }

  DiskPoint next() {
    const auto x = static_cast<std::int32_t>(lanes_.next(lane_));
    const auto y = static_cast<std::int32_t>(lanes_.next(lane_));
    lane_ = (lane_ + 1) % k_lanes;
    return {x, y};
  }

  /// The generators, for the fast counter that advances all lanes by whole rounds (16
  /// points) while next() is at lane 0, which leaves it at lane 0.
  Lanes& lanes() { return lanes_; }

 private:
  Lanes lanes_;
  int lane_ = 0;
};

/// The lecture's estimator of the disk's area, from n >= 1 points:
///
///   M = 0
///   for i < N: (x, y) uniform in [-1, 1]^2; if x^2 + y^2 <= 1: M = M + 1
///   return 4 M / N                              E = pi,  V = 16 p (1 - p) / N
///
/// count_in_disk (integration/disk_counter.hpp) counts the same M from the same `rng`, 16
/// lanes at a time; the chapter runs that engine.
inline double estimate_disk_area(std::uint64_t n, Rng& rng) {
  // ASSIGNMENT a1.1 BEGIN stub: (void)n; (void)rng; NOT_IMPLEMENTED(estimate_disk_area);
  DiskPoints points(rng);
  std::uint64_t m = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const DiskPoint p = points.next();  // (x, y) uniform in [-1, 1)^2
    if (inside_unit_disk(p)) ++m;       // x^2 + y^2 <= 1
  }
  return 4.0 * static_cast<double>(m) / static_cast<double>(n);
  // ASSIGNMENT a1.1 END
}

/// M: how many of n uniform points of [-1,1)^k land in the unit k-ball, 0 <= k <=
/// k_max_ball_dims; coordinate 2 u - 1 with u = rng.uniform(), tested by inside_unit_ball.
std::uint64_t count_in_ball(int k, std::uint64_t n, Rng& rng);

/// The k-ball's volume estimate 2^k M / N from n >= 1 points: E = V_k,
/// V = 4^k q (1 - q) / N with q = V_k / 2^k.
double estimate_ball_volume(int k, std::uint64_t n, Rng& rng);

}  // namespace mcrt
