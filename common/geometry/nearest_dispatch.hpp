#pragma once
/// The one choice the primitive sets (QuadSet, SphereSet) make between their AVX2 search and
/// their portable one, from what the processor runs (asked once, at start-up). A set derives
/// from NearestDispatch<Set> and defines size(), nearest_portable, nearest_avx2,
/// nearest_lanes_portable and nearest_lanes_avx2; the two answers are the same bit for bit.

#include "geometry/ray.hpp"
#include "geometry/ray_lanes.hpp"

namespace mcrt {

/// Whether this processor runs AVX2, for every primitive set (nearest_dispatch.cpp).
struct Avx2Choice {
  static const bool k_has_avx2;
};

template <class Set>
class NearestDispatch : private Avx2Choice {
 public:
  /// nearest_avx2 where the processor has AVX2, nearest_portable elsewhere; no call at all
  /// for a set without primitives (inline, so that costs one predictable branch).
  auto nearest(const Ray& ray, Interval range) const {
    const Set& set = static_cast<const Set&>(*this);
    using Nearest = typename Set::Nearest;
    if (set.size() == 0) return Nearest{0, range.max};
    return k_has_avx2 ? set.nearest_avx2(ray, range) : set.nearest_portable(ray, range);
  }

  /// Four rays at once: each lane of `nearest` becomes the nearest primitive of its ray hit in
  /// (t_min, nearest.t[lane]), if there is one nearer than what the lane holds; the same t and
  /// index, bit for bit, as nearest() of each ray alone.
  void nearest_lanes(const RayLanes& rays, double t_min, NearestLanes& nearest) const {
    const Set& set = static_cast<const Set&>(*this);
    if (set.size() == 0) return;
    if (k_has_avx2)
      set.nearest_lanes_avx2(rays, t_min, nearest);
    else
      set.nearest_lanes_portable(rays, t_min, nearest);
  }

  /// Whether this processor runs AVX2 (checked once, at start-up).
  static bool has_avx2() { return k_has_avx2; }
};

}  // namespace mcrt
