#pragma once
/// The quads of a scene as a structure of arrays, for the closest-hit loop: what SphereSet
/// does for spheres.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/nearest_dispatch.hpp"
#include "geometry/quad.hpp"
#include "geometry/ray_lanes.hpp"

namespace mcrt {

/// Plane normals, edge axes and their offsets in separate arrays, in runs of whole blocks of
/// k_block slots, padded with quads that never hit (a parallel-ray threshold of +infinity), so
/// the search runs k_block quads at a time with no remainder loop. A run is either quads added one
/// by one, or a group (add_group) behind its bounding box, which a ray that misses the box
/// skips. Each quad's t, a and b are computed with the same operations, in the same order, as
/// intersect_distance (quad.hpp), and the quads a ray is tested against are tested in index
/// order, so the answer is the same bit for bit. (The four-ray search leaves out the products
/// by zero of quads whose vectors have zero coordinates, such as a box's walls: for finite
/// rays and t_min >= 0 that changes no answer, only, at most, the sign of a zero that no test
/// can tell apart.)
class QuadSet : public NearestDispatch<QuadSet> {
 public:
  static constexpr std::size_t k_block = 4;  ///< doubles in one AVX2 register

  /// The quad hit nearest in `range`; index == size() if none. Ties go to the lowest index,
  /// as in a plain loop that keeps the first strictly nearer hit.
  struct Nearest {
    std::size_t index;
    double t;
  };

  /// A quad every ray is tested against.
  void add(const Quad& q);
  /// Quads that enclose a small part of the scene, such as the six faces of a box, with the
  /// next indices: the AVX2 searches test them only for rays that meet their common bounds
  /// (padded, so no hit on them is ever skipped). The portable searches test every quad.
  void add_group(std::span<const Quad> quads);
  std::size_t size() const { return size_; }

  /// nearest(ray, range) (NearestDispatch) runs one of these two.
  /// Plain C++, one quad at a time.
  Nearest nearest_portable(const Ray& ray, Interval range) const;
  /// Four quads per instruction; only call it if has_avx2().
  Nearest nearest_avx2(const Ray& ray, Interval range) const;

  /// nearest_lanes(rays, t_min, nearest) (NearestDispatch) runs one of these two: for finite
  /// rays and t_min >= 0, the same t and index, bit for bit, as nearest() of each ray alone.
  /// Plain C++, one ray and one quad at a time.
  void nearest_lanes_portable(const RayLanes& rays, double t_min, NearestLanes& nearest) const;
  /// One quad against the four rays per instruction; only call it if has_avx2().
  void nearest_lanes_avx2(const RayLanes& rays, double t_min, NearestLanes& nearest) const;

 private:
  /// Slots [begin, end) (whole blocks) holding quads first, first + 1, ..., first + count - 1,
  /// then padding: quads added one by one, or a group behind its box.
  struct Run {
    std::size_t begin, end, first, count;
    bool bounded;
    std::size_t box = 0;  ///< a group's number among the groups: its box's slot below
  };
  void add_block();
  void put(std::size_t slot, const Quad& q);

  std::vector<Run> runs_;
  std::size_t size_ = 0;
  /// The groups' boxes, padded (every point of a group's quads is inside its box), coordinate
  /// by coordinate, k_block to a block (the last block padded with zeros, never read): the
  /// one-ray search tests four boxes per instruction, the four-ray search one box in every lane.
  std::vector<double> box_low_[3], box_high_[3];
  std::size_t groups_ = 0;
  // Per slot, coordinate by coordinate (0, 1, 2: x, y, z): n = cross(u, v) (not normalised)
  // and the axes giving the edge coordinates; then the offsets n.corner, axis_a.corner and
  // axis_b.corner, the parallel-ray threshold 1e-12 |n|, and the quad's index (as a double,
  // exact below 2^53; -1 in padding).
  std::vector<double> normal_[3], axis_a_[3], axis_b_[3];
  std::vector<double> plane_offset_, offset_a_, offset_b_;
  std::vector<double> parallel_threshold_;
  std::vector<double> index_;
  /// One quad's values side by side, for the four-ray search, which reads one quad at a time
  /// (one base address, instead of one per array).
  struct Record {
    double normal[3], axis_a[3], axis_b[3];
    double plane_offset, offset_a, offset_b, parallel_threshold, index;
    /// 1 when each of n, axis_a and axis_b has one coordinate that is not zero (a quad in a
    /// coordinate plane with its edges along the axes: a box's walls), 2 when each has at most
    /// two (a box turned about an axis: its sides), 3 otherwise. `coordinate` gives, for n,
    /// axis_a and axis_b, the coordinates whose products the search sums.
    std::int32_t terms = 3;
    std::int32_t coordinate[3][3]{};
  };
  std::vector<Record> records_;
};

}  // namespace mcrt
