#include "geometry/quad_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/cpu_features.hpp"
#include "geometry/avx2_lanes.hpp"

namespace mcrt {

const bool QuadSet::k_has_avx2 = cpu_has_avx2();

void QuadSet::add(const Quad& q) {
  // Quads added one by one share a run, which grows a block at a time.
  if (runs_.empty() || runs_.back().bounded)
    runs_.push_back({index_.size(), index_.size(), size_, 0, false, {}, {}});
  Run& run = runs_.back();
  if (run.begin + run.count == run.end) {
    add_block();
    run.end = index_.size();
  }
  put(run.begin + run.count++, q);
}

void QuadSet::add_group(std::span<const Quad> quads) {
  if (quads.empty()) return;
  Run run{index_.size(), index_.size(), size_, 0, true, {}, {}};
  while (index_.size() < run.begin + quads.size()) add_block();
  run.end = index_.size();
  Vec3 low(std::numeric_limits<double>::infinity()), high(-low);
  for (const Quad& q : quads) {
    put(run.begin + run.count++, q);
    for (const Vec3& p : {q.corner(), q.corner() + q.edge_u(), q.corner() + q.edge_v(),
                          q.corner() + q.edge_u() + q.edge_v()}) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
  }
  // The pad, a millionth of the group's largest coordinate (at least 1), is far above the
  // rounding of a hit point's coordinates (about 1e-16 of them), so a ray that hits a quad of
  // the group meets the padded box around that point with room to spare, whatever the rounding
  // of either test.
  double scale = 1.0;
  for (int axis = 0; axis < 3; ++axis)
    scale = std::max({scale, std::abs(low[axis]), std::abs(high[axis])});
  const double pad = 1e-6 * scale;
  for (int axis = 0; axis < 3; ++axis) {
    run.low[axis] = low[axis] - pad;
    run.high[axis] = high[axis] + pad;
  }
  runs_.push_back(run);
}

void QuadSet::add_block() {
  for (std::vector<double>* v : {&normal_x_, &normal_y_, &normal_z_, &corner_x_, &corner_y_,
                                 &corner_z_, &axis_a_x_, &axis_a_y_, &axis_a_z_, &axis_b_x_,
                                 &axis_b_y_, &axis_b_z_})
    v->resize(v->size() + k_block, 0.0);
  // |n.d| < +infinity always: a padding quad is never hit.
  parallel_threshold_.resize(parallel_threshold_.size() + k_block,
                             std::numeric_limits<double>::infinity());
  index_.resize(index_.size() + k_block, -1.0);
}

void QuadSet::put(std::size_t slot, const Quad& q) {
  normal_x_[slot] = q.plane_normal().x;
  normal_y_[slot] = q.plane_normal().y;
  normal_z_[slot] = q.plane_normal().z;
  corner_x_[slot] = q.corner().x;
  corner_y_[slot] = q.corner().y;
  corner_z_[slot] = q.corner().z;
  axis_a_x_[slot] = q.axis_a().x;
  axis_a_y_[slot] = q.axis_a().y;
  axis_a_z_[slot] = q.axis_a().z;
  axis_b_x_[slot] = q.axis_b().x;
  axis_b_y_[slot] = q.axis_b().y;
  axis_b_z_[slot] = q.axis_b().z;
  parallel_threshold_[slot] = q.parallel_threshold();
  index_[slot] = static_cast<double>(size_++);
}

// intersect_distance for every quad, chosen between with selects rather than early exits (a
// mispredicted branch costs more than the arithmetic it would skip).
QuadSet::Nearest QuadSet::nearest_portable(const Ray& ray, Interval range) const {
  Nearest best{size_, range.max};
  for (const Run& run : runs_)
    for (std::size_t k = 0; k < run.count; ++k) {
      const std::size_t s = run.begin + k;  // the slot of quad run.first + k
      const Vec3 n(normal_x_[s], normal_y_[s], normal_z_[s]);
      const Vec3 corner(corner_x_[s], corner_y_[s], corner_z_[s]);
      const double denom = glm::dot(n, ray.direction);
      const double t = glm::dot(n, corner - ray.origin) / denom;
      const Vec3 p = ray.at(t) - corner;
      const double a = glm::dot(p, Vec3(axis_a_x_[s], axis_a_y_[s], axis_a_z_[s]));
      const double b = glm::dot(p, Vec3(axis_b_x_[s], axis_b_y_[s], axis_b_z_[s]));
      const bool closer = !(std::abs(denom) < parallel_threshold_[s]) && t > range.min &&
                          t < best.t && !(a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0);
      best.t = closer ? t : best.t;
      best.index = closer ? run.first + k : best.index;
    }
  return best;
}

void QuadSet::nearest_lanes_portable(const RayLanes& rays, double t_min,
                                     NearestLanes& nearest) const {
  for (int l = 0; l < RayLanes::k_lanes; ++l) {
    const Nearest best = nearest_portable(rays.get(l), {t_min, nearest.t[l]});
    if (best.index == size_) continue;
    nearest.t[l] = best.t;
    nearest.index[l] = static_cast<double>(best.index);
  }
}

#if MCRT_X86

namespace {

// (x1 y1 + x2 y2) + x3 y3, summed in glm::dot's order.
[[gnu::target("avx2")]] inline __m256d dot(__m256d x1, __m256d x2, __m256d x3, __m256d y1,
                                          __m256d y2, __m256d y3) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x1, y1), _mm256_mul_pd(x2, y2)),
                       _mm256_mul_pd(x3, y3));
}

// Whether any of four rays o + t d, t in (t_min, t_max), meets the box [low, high]: the slab
// test, with 1/d precomputed. Where d has a zero coordinate, 1/d is infinite and the slab of
// that axis is all of t (o inside it) or none (o outside). An origin exactly on a face plane of
// the box, running in that plane, gives 0 x infinity = NaN: min and max (which return their
// second operand if either is NaN) then either drop that axis's limit or make the lane miss.
// Both are safe: such a ray stays the pad away from every quad of the group.
[[gnu::target("avx2")]] inline bool any_lane_meets_box(const double low[3], const double high[3],
                                                      const __m256d origin[3],
                                                      const __m256d inverse_d[3], __m256d t_min,
                                                      __m256d t_max) {
  __m256d enter = t_min, leave = t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const __m256d t_low =
        _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(low[axis]), origin[axis]), inverse_d[axis]);
    const __m256d t_high =
        _mm256_mul_pd(_mm256_sub_pd(_mm256_set1_pd(high[axis]), origin[axis]), inverse_d[axis]);
    enter = _mm256_max_pd(_mm256_min_pd(t_low, t_high), enter);
    leave = _mm256_min_pd(_mm256_max_pd(t_low, t_high), leave);
  }
  return _mm256_movemask_pd(_mm256_cmp_pd(enter, leave, _CMP_LE_OQ)) != 0;
}

}  // namespace

// The loop of nearest_portable on four quads per instruction, each lane keeping its own
// nearest t and index; the lanes are merged at the end (nearest t, then lowest index). Only
// AVX2 is enabled, not FMA: a fused multiply-add would round differently from the plain loop.
// A group is skipped when the ray misses its box before the nearest hit so far.
[[gnu::target("avx2")]] QuadSet::Nearest QuadSet::nearest_avx2(const Ray& ray,
                                                               Interval range) const {
  const __m256d ox = _mm256_set1_pd(ray.origin.x), oy = _mm256_set1_pd(ray.origin.y),
                oz = _mm256_set1_pd(ray.origin.z);
  const __m256d dx = _mm256_set1_pd(ray.direction.x), dy = _mm256_set1_pd(ray.direction.y),
                dz = _mm256_set1_pd(ray.direction.z);
  const __m256d t_min = _mm256_set1_pd(range.min), zero = _mm256_setzero_pd(),
                one = _mm256_set1_pd(1.0), sign = _mm256_set1_pd(-0.0);
  const __m256d origin[3] = {ox, oy, oz};
  const __m256d inverse_d[3] = {_mm256_div_pd(one, dx), _mm256_div_pd(one, dy),
                                _mm256_div_pd(one, dz)};
  __m256d best_t = _mm256_set1_pd(range.max);
  __m256d best_index = _mm256_set1_pd(-1.0);  // indices as doubles: exact below 2^53
  for (const Run& run : runs_) {
    if (run.bounded && !any_lane_meets_box(run.low, run.high, origin, inverse_d, t_min,
                                           avx2::all_lanes_min(best_t)))
      continue;
    for (std::size_t i = run.begin; i < run.end; i += k_block) {
      const __m256d nx = _mm256_loadu_pd(&normal_x_[i]), ny = _mm256_loadu_pd(&normal_y_[i]),
                    nz = _mm256_loadu_pd(&normal_z_[i]);
      const __m256d cx = _mm256_loadu_pd(&corner_x_[i]), cy = _mm256_loadu_pd(&corner_y_[i]),
                    cz = _mm256_loadu_pd(&corner_z_[i]);
      const __m256d denom = dot(nx, ny, nz, dx, dy, dz);
      const __m256d t = _mm256_div_pd(
          dot(nx, ny, nz, _mm256_sub_pd(cx, ox), _mm256_sub_pd(cy, oy), _mm256_sub_pd(cz, oz)),
          denom);
      // p = (o + t d) - c, as ray.at(t) - corner.
      const __m256d px = _mm256_sub_pd(_mm256_add_pd(ox, _mm256_mul_pd(t, dx)), cx);
      const __m256d py = _mm256_sub_pd(_mm256_add_pd(oy, _mm256_mul_pd(t, dy)), cy);
      const __m256d pz = _mm256_sub_pd(_mm256_add_pd(oz, _mm256_mul_pd(t, dz)), cz);
      const __m256d a = dot(px, py, pz, _mm256_loadu_pd(&axis_a_x_[i]),
                            _mm256_loadu_pd(&axis_a_y_[i]), _mm256_loadu_pd(&axis_a_z_[i]));
      const __m256d b = dot(px, py, pz, _mm256_loadu_pd(&axis_b_x_[i]),
                            _mm256_loadu_pd(&axis_b_y_[i]), _mm256_loadu_pd(&axis_b_z_[i]));
      // !(|denom| < threshold): NaN-safe in the same way as the plain comparison.
      const __m256d facing = _mm256_cmp_pd(_mm256_andnot_pd(sign, denom),
                                           _mm256_loadu_pd(&parallel_threshold_[i]), _CMP_NLT_UQ);
      const __m256d in_range = _mm256_and_pd(_mm256_cmp_pd(t, t_min, _CMP_GT_OQ),
                                             _mm256_cmp_pd(t, best_t, _CMP_LT_OQ));
      // !(a < 0 || a > 1 || b < 0 || b > 1), NaN-safe in the same way as the plain test.
      const __m256d inside = _mm256_and_pd(
          _mm256_and_pd(_mm256_cmp_pd(a, zero, _CMP_NLT_UQ), _mm256_cmp_pd(a, one, _CMP_NGT_UQ)),
          _mm256_and_pd(_mm256_cmp_pd(b, zero, _CMP_NLT_UQ), _mm256_cmp_pd(b, one, _CMP_NGT_UQ)));
      const __m256d closer = _mm256_and_pd(_mm256_and_pd(facing, in_range), inside);
      best_t = _mm256_blendv_pd(best_t, t, closer);
      best_index = _mm256_blendv_pd(best_index, _mm256_loadu_pd(&index_[i]), closer);
    }
  }
  const avx2::NearestLane nearest = avx2::merge_lanes(best_t, best_index);
  if (nearest.index < 0.0) return {size_, range.max};
  return {static_cast<std::size_t>(nearest.index), nearest.t};
}

// nearest_portable's loop body with one quad broadcast to the four lanes and a ray in each:
// every lane does what the one-ray loop does, in the same order, so no lanes are merged at
// the end. The padding slots are skipped: only each run's quads are read.
//
// A group's quads are skipped when none of the four rays meets its box within its range
// (t_min, nearest t so far): a quad the box does not meet cannot be hit, so skipping it
// changes no lane's answer, and the quads that are tested are tested in index order, as before.
[[gnu::target("avx2")]] void QuadSet::nearest_lanes_avx2(const RayLanes& rays, double t_min,
                                                         NearestLanes& nearest) const {
  const __m256d ox = _mm256_load_pd(rays.origin_x), oy = _mm256_load_pd(rays.origin_y),
                oz = _mm256_load_pd(rays.origin_z);
  const __m256d dx = _mm256_load_pd(rays.direction_x), dy = _mm256_load_pd(rays.direction_y),
                dz = _mm256_load_pd(rays.direction_z);
  const __m256d t_low = _mm256_set1_pd(t_min), zero = _mm256_setzero_pd(),
                one = _mm256_set1_pd(1.0), sign = _mm256_set1_pd(-0.0);
  __m256d best_t = _mm256_load_pd(nearest.t);
  __m256d best_index = _mm256_load_pd(nearest.index);
  const __m256d inverse_d[3] = {_mm256_div_pd(one, dx), _mm256_div_pd(one, dy),
                                _mm256_div_pd(one, dz)};
  const __m256d origin[3] = {ox, oy, oz};
  for (const Run& run : runs_) {
    if (run.bounded && !any_lane_meets_box(run.low, run.high, origin, inverse_d, t_low, best_t))
      continue;
    for (std::size_t i = run.begin; i < run.begin + run.count; ++i) {
      const __m256d nx = _mm256_set1_pd(normal_x_[i]), ny = _mm256_set1_pd(normal_y_[i]),
                    nz = _mm256_set1_pd(normal_z_[i]);
      const __m256d cx = _mm256_set1_pd(corner_x_[i]), cy = _mm256_set1_pd(corner_y_[i]),
                    cz = _mm256_set1_pd(corner_z_[i]);
      const __m256d denom = dot(nx, ny, nz, dx, dy, dz);
      const __m256d t = _mm256_div_pd(
          dot(nx, ny, nz, _mm256_sub_pd(cx, ox), _mm256_sub_pd(cy, oy), _mm256_sub_pd(cz, oz)),
          denom);
      const __m256d px = _mm256_sub_pd(_mm256_add_pd(ox, _mm256_mul_pd(t, dx)), cx);
      const __m256d py = _mm256_sub_pd(_mm256_add_pd(oy, _mm256_mul_pd(t, dy)), cy);
      const __m256d pz = _mm256_sub_pd(_mm256_add_pd(oz, _mm256_mul_pd(t, dz)), cz);
      const __m256d a = dot(px, py, pz, _mm256_set1_pd(axis_a_x_[i]),
                            _mm256_set1_pd(axis_a_y_[i]), _mm256_set1_pd(axis_a_z_[i]));
      const __m256d b = dot(px, py, pz, _mm256_set1_pd(axis_b_x_[i]),
                            _mm256_set1_pd(axis_b_y_[i]), _mm256_set1_pd(axis_b_z_[i]));
      const __m256d facing = _mm256_cmp_pd(_mm256_andnot_pd(sign, denom),
                                           _mm256_set1_pd(parallel_threshold_[i]), _CMP_NLT_UQ);
      const __m256d in_range = _mm256_and_pd(_mm256_cmp_pd(t, t_low, _CMP_GT_OQ),
                                             _mm256_cmp_pd(t, best_t, _CMP_LT_OQ));
      const __m256d inside = _mm256_and_pd(
          _mm256_and_pd(_mm256_cmp_pd(a, zero, _CMP_NLT_UQ), _mm256_cmp_pd(a, one, _CMP_NGT_UQ)),
          _mm256_and_pd(_mm256_cmp_pd(b, zero, _CMP_NLT_UQ), _mm256_cmp_pd(b, one, _CMP_NGT_UQ)));
      const __m256d closer = _mm256_and_pd(_mm256_and_pd(facing, in_range), inside);
      best_t = _mm256_blendv_pd(best_t, t, closer);
      best_index = _mm256_blendv_pd(best_index, _mm256_set1_pd(index_[i]), closer);
    }
  }
  _mm256_store_pd(nearest.t, best_t);
  _mm256_store_pd(nearest.index, best_index);
}

#else

QuadSet::Nearest QuadSet::nearest_avx2(const Ray& ray, Interval range) const {
  return nearest_portable(ray, range);
}

void QuadSet::nearest_lanes_avx2(const RayLanes& rays, double t_min,
                                 NearestLanes& nearest) const {
  nearest_lanes_portable(rays, t_min, nearest);
}

#endif

}  // namespace mcrt
