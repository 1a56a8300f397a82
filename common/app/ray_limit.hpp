#pragma once
/// Refusing, before any work, a run that would trace too many rays (app/work_limit.hpp for
/// other work).

#include <string_view>

namespace mcrt {

/// The speed a refusal quotes: bench_recursive_estimator's Cornell box on one core of the
/// machine these chapters were written on measured 2.6-2.9 million rays per second.
inline constexpr double k_estimated_rays_per_second_per_thread = 2.5e6;

/// The most rays one chapter run may trace: about 1.4 hours at 2e7 rays per second.
inline constexpr double k_max_rays = 1e11;

/// A run's predicted rays (an upper bound; a double, as a request may exceed 2^64) and, in
/// words, what the prediction counts.
struct RayWork {
  double predicted_rays = 0.0;
  std::string_view counted;  ///< e.g. "2 renders x sum of spp x pixels x (depth + 1)"
};

/// Throws UsageError (exit 2) if work.predicted_rays > limit: one line naming `flags`, the
/// count, about how long it would take on `threads` threads, the limit and `remedy`.
void check_ray_limit(const RayWork& work, double limit, std::string_view flags, int threads,
                     std::string_view remedy);

/// Throws UsageError naming --albedo at an albedo of 1 or more: Le / (1 - a) is infinite.
void check_furnace_albedo(double albedo);

/// Mean vertices of a furnace path (albedo a everywhere) ended by Russian roulette after
/// `min_depth`: the throughput policy continues with q = a, so the length is geometric,
/// min_depth + 1 / (1 - a): a million vertices per sample at a = 0.999999.
inline double furnace_path_vertices(double albedo, int min_depth) {
  return min_depth + 1.0 / (1.0 - albedo);
}

}  // namespace mcrt
