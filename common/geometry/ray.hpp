#pragma once
/// A ray o + t d, t in (t_min, t_max).

#include <cstdint>
#include <limits>

#include "core/math.hpp"

namespace mcrt {

struct Ray {
  Vec3 origin;
  Vec3 direction;  ///< unit length

  Ray() = default;
  Ray(const Vec3& origin_, const Vec3& direction_) : origin(origin_), direction(direction_) {}
  Ray(const Ray&) = default;
  /// Assigned coordinate by coordinate. The default assignment copies the six doubles in
  /// 16-byte pieces; in the path loop, `ray = spawn_ray(...)` copies a ray that was just
  /// written in 8-byte pieces, and a load that straddles two pending stores cannot take its
  /// bytes from them: it waits for them to reach the cache, every bounce. 1.13x the path
  /// tracer's rays/s on cornell-spheres, 1.09x on cornell (bench_path_tracer, alternating runs).
  Ray& operator=(const Ray& other) {
    origin.x = other.origin.x;
    origin.y = other.origin.y;
    origin.z = other.origin.z;
    direction.x = other.direction.x;
    direction.y = other.direction.y;
    direction.z = other.direction.z;
    return *this;
  }

  Vec3 at(double t) const { return origin + t * direction; }
};

/// Where along a ray intersections count. t_min > 0 keeps a ray from re-hitting its origin.
struct Interval {
  double min = 1e-9;
  double max = std::numeric_limits<double>::infinity();
  bool contains(double t) const { return t > min && t < max; }
};

/// Rays traced by an estimator: one per closest-hit or any-hit query.
struct RayCount {
  std::uint64_t rays = 0;
};

}  // namespace mcrt
