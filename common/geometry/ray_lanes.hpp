#pragma once
/// Four rays side by side, coordinate by coordinate, for the searches that test one primitive
/// against four rays at once (SphereSet::nearest_lanes, QuadSet::nearest_lanes).
///
/// Testing four primitives against one ray (SphereSet::nearest) leaves the four lanes to be
/// merged at the end of every query; four rays against one primitive need no merge: each lane
/// is one ray's own search, the same one the one-ray loop does.

#include <cstddef>
#include <cstdint>

#include "geometry/ray.hpp"

namespace mcrt {

struct RayLanes {
  static constexpr int k_lanes = 4;  ///< doubles in one AVX2 register
  alignas(32) double origin_x[k_lanes]{}, origin_y[k_lanes]{}, origin_z[k_lanes]{};
  alignas(32) double direction_x[k_lanes]{}, direction_y[k_lanes]{}, direction_z[k_lanes]{};

  void set(int lane, const Ray& ray) {
    origin_x[lane] = ray.origin.x;
    origin_y[lane] = ray.origin.y;
    origin_z[lane] = ray.origin.z;
    direction_x[lane] = ray.direction.x;
    direction_y[lane] = ray.direction.y;
    direction_z[lane] = ray.direction.z;
  }
  Ray get(int lane) const {
    return {{origin_x[lane], origin_y[lane], origin_z[lane]},
            {direction_x[lane], direction_y[lane], direction_z[lane]}};
  }
};

/// Each lane's nearest hit so far: its t and the primitive's index as a double (exact below
/// 2^53), -1 for none. A search reads t as the end of the lane's range and lowers it.
struct NearestLanes {
  alignas(32) double t[RayLanes::k_lanes];
  alignas(32) double index[RayLanes::k_lanes];

  /// No hit yet in any lane, and every lane's range ending at `t_max`.
  explicit NearestLanes(double t_max) {
    for (int l = 0; l < RayLanes::k_lanes; ++l) {
      t[l] = t_max;
      index[l] = -1.0;
    }
  }
  bool found(int lane) const { return index[lane] >= 0.0; }
  std::size_t primitive(int lane) const { return static_cast<std::size_t>(index[lane]); }
};

/// Four rays' hits, coordinate by coordinate (axis 0, 1, 2: x, y, z): what Hit holds, for each
/// lane, with material -1 in a lane whose ray hit nothing.
struct HitLanes {
  alignas(32) double point[3][RayLanes::k_lanes]{};
  alignas(32) double normal[3][RayLanes::k_lanes]{};  ///< unit, facing the incoming ray
  std::int64_t material[RayLanes::k_lanes]{};

  bool found(int lane) const { return material[lane] >= 0; }
};

}  // namespace mcrt
