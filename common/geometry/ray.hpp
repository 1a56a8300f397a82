#pragma once
/// A ray o + t d, t in (t_min, t_max).

#include <cstdint>
#include <limits>

#include "core/math.hpp"

namespace mcrt {

struct Ray {
  Vec3 origin;
  Vec3 direction;  ///< unit length
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
