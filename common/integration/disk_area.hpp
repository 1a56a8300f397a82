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
/// Points are lattice points: a coordinate is a 32-bit integer j / 2^31, j in [-2^31, 2^31).
/// The lattice's hit fraction differs from p by the lattice-point error of the ball, about
/// 1e-12 relative for the disk: no experiment of fewer than 1e20 points can see it.

#include <cstdint>

#include "core/math.hpp"
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

/// M: how many of n uniform points of [-1,1)^2 land in the unit disk (x^2 + y^2 <= 1).
/// The points come from 16 PCG32 lanes seeded from `rng`; point i is drawn by lane i mod 16.
/// The test is exact in 64-bit integers, and uses AVX2 when the processor has it: the count
/// is the same either way.
std::uint64_t count_in_disk(std::uint64_t n, Rng& rng);
/// The same count without AVX2 (the reference the fast path must equal).
std::uint64_t count_in_disk_portable(std::uint64_t n, Rng& rng);
/// Whether count_in_disk runs its AVX2 path on this processor.
bool disk_count_uses_avx2();

/// The disk's area estimate 4 M / N from n >= 1 points: E = pi, V = 16 p (1 - p) / N.
double estimate_disk_area(std::uint64_t n, Rng& rng);

/// Points per chunk of count_in_disk_parallel: ~4 ms of work, enough to hide the hand-over.
inline constexpr std::uint64_t k_disk_chunk = std::uint64_t{1} << 22;

/// M for n points on `threads` threads. The points are split into chunks of k_disk_chunk;
/// chunk j draws from Rng(seed, stream_index(stream, j)), so M does not depend on `threads`.
std::uint64_t count_in_disk_parallel(std::uint64_t n, std::uint64_t seed, std::uint64_t stream,
                                     int threads);

/// M: how many of n uniform points of [-1,1)^k land in the unit k-ball, 0 <= k <=
/// k_max_ball_dims; coordinate 2 u - 1 with u = rng.uniform(), tested by inside_unit_ball.
std::uint64_t count_in_ball(int k, std::uint64_t n, Rng& rng);

/// The k-ball's volume estimate 2^k M / N from n >= 1 points: E = V_k,
/// V = 4^k q (1 - q) / N with q = V_k / 2^k.
double estimate_ball_volume(int k, std::uint64_t n, Rng& rng);

}  // namespace mcrt
