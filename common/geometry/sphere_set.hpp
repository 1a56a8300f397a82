#pragma once
/// The spheres of a scene as a structure of arrays, for the closest-hit loop.

#include <cstddef>
#include <vector>

#include "geometry/nearest_dispatch.hpp"
#include "geometry/ray_lanes.hpp"
#include "geometry/sphere.hpp"

namespace mcrt {

/// Centres and squared radii in separate arrays, padded to whole blocks of k_block spheres
/// that never hit (r^2 = -infinity), so the nearest-root search runs k_block spheres at a
/// time with no remainder loop. Each sphere's t is computed with the same operations, in the
/// same order, as intersect_distance (sphere.hpp), so the answer is the same bit for bit.
class SphereSet : public NearestDispatch<SphereSet> {
 public:
  static constexpr std::size_t k_block = 4;  ///< doubles in one AVX2 register

  /// The sphere whose root in `range` is nearest; index == size() if none. Ties go to the
  /// lowest index, as in a plain loop that keeps the first strictly nearer hit.
  struct Nearest {
    std::size_t index;
    double t;
  };

  void add(const Sphere& s);
  std::size_t size() const { return size_; }
  /// 1 / radius of sphere i, kept so that hit_at need not divide.
  double inverse_radius(std::size_t i) const { return inverse_radius_[i]; }

  /// nearest(ray, range) (NearestDispatch) runs one of these two.
  /// Plain C++, one sphere at a time.
  Nearest nearest_portable(const Ray& ray, Interval range) const;
  /// Four spheres per instruction; only call it if has_avx2().
  Nearest nearest_avx2(const Ray& ray, Interval range) const;

  /// nearest_lanes(rays, t_min, nearest) (NearestDispatch) runs one of these two.
  /// Plain C++, one ray and one sphere at a time.
  void nearest_lanes_portable(const RayLanes& rays, double t_min, NearestLanes& nearest) const;
  /// One sphere against the four rays per instruction; only call it if has_avx2().
  void nearest_lanes_avx2(const RayLanes& rays, double t_min, NearestLanes& nearest) const;

 private:
  std::size_t size_ = 0;
  std::vector<double> center_x_, center_y_, center_z_, radius_squared_;
  std::vector<double> inverse_radius_;  ///< not padded: only read for a sphere that was hit
};

}  // namespace mcrt
