#pragma once
/// Refusing a run too large to finish, before any work is done: a chapter predicts from its
/// flags how many rays the run would trace and compares that with a limit.

#include <string_view>

namespace mcrt {

/// The speed quoted when a run is refused (nothing has been measured yet): what
/// bench_recursive_estimator measured for the Cornell box on one core of the machine these
/// chapters were written on (2.6-2.9 million rays per second).
inline constexpr double k_estimated_rays_per_second_per_thread = 2.5e6;

/// The most rays one chapter run may trace: about 1.4 hours at 2e7 rays per second.
inline constexpr double k_max_rays = 1e11;

/// What a refused run would have been: its predicted rays (an upper bound, and a double since a
/// request may exceed 2^64) and, in words, what the prediction counts.
struct RayWork {
  double predicted_rays = 0.0;
  std::string_view counted;  ///< e.g. "2 renders x sum of spp x pixels x (depth + 1)"
};

/// Throws UsageError (exit code 2) if work.predicted_rays > limit, with one line naming `flags`,
/// the predicted count, about how long it would take on `threads` threads (at
/// k_estimated_rays_per_second_per_thread), the limit and `remedy` (what to change).
void check_ray_limit(const RayWork& work, double limit, std::string_view flags, int threads,
                     std::string_view remedy);

/// Throws UsageError (exit code 2) naming --albedo if the furnace's albedo is 1 or more: its
/// radiance Le / (1 - a) is infinite, and paths that end only by absorption never end.
void check_furnace_albedo(double albedo);

/// Mean vertices of a path in the furnace (the same albedo a on every surface) that ends by
/// Russian roulette after `min_depth` vertices: its weight, divided by q, stays 1, so the
/// throughput policy goes on with q = a at every later vertex, and the mean length is
/// min_depth + 1 / (1 - a) (geometric). At a = 0.999999 that is a million vertices per sample.
inline double furnace_path_vertices(double albedo, int min_depth) {
  return min_depth + 1.0 / (1.0 - albedo);
}

}  // namespace mcrt
