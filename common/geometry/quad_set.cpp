#include "geometry/quad_set.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/avx2_lanes.hpp"

namespace mcrt {

void QuadSet::add(const Quad& q) {
  // Quads added one by one share a run, which grows a block at a time.
  if (runs_.empty() || runs_.back().bounded)
    runs_.push_back({index_.size(), index_.size(), size_, 0, false});
  Run& run = runs_.back();
  if (run.begin + run.count == run.end) {
    add_block();
    run.end = index_.size();
  }
  put(run.begin + run.count++, q);
}

void QuadSet::add_group(std::span<const Quad> quads) {
  if (quads.empty()) return;
  Run run{index_.size(), index_.size(), size_, 0, true};
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
  run.box = groups_++;
  if (run.box % k_block == 0)
    for (int axis = 0; axis < 3; ++axis) {
      box_low_[axis].resize(box_low_[axis].size() + k_block, 0.0);
      box_high_[axis].resize(box_high_[axis].size() + k_block, 0.0);
    }
  for (int axis = 0; axis < 3; ++axis) {
    box_low_[axis][run.box] = low[axis] - pad;
    box_high_[axis][run.box] = high[axis] + pad;
  }
  runs_.push_back(run);
}

void QuadSet::add_block() {
  for (int axis = 0; axis < 3; ++axis)
    for (std::vector<double>* v : {&normal_[axis], &axis_a_[axis], &axis_b_[axis]})
      v->resize(v->size() + k_block, 0.0);
  for (std::vector<double>* v : {&plane_offset_, &offset_a_, &offset_b_})
    v->resize(v->size() + k_block, 0.0);
  // |n.d| < +infinity always: a padding quad is never hit.
  parallel_threshold_.resize(parallel_threshold_.size() + k_block,
                             std::numeric_limits<double>::infinity());
  index_.resize(index_.size() + k_block, -1.0);
  records_.resize(records_.size() + k_block);
}

namespace {

// How many coordinates of v are not zero.
int nonzero_coordinates(const Vec3& v) { return (v.x != 0.0) + (v.y != 0.0) + (v.z != 0.0); }

// The `terms` coordinates whose products make v's dot products. All three: 0, 1, 2, glm::dot's
// own order. Fewer: those of v that are not zero, then (for two terms and a v with one) a
// coordinate that is, which only adds a product by zero.
void sum_coordinates(const Vec3& v, int terms, std::int32_t coordinate[3]) {
  if (terms == 3) {
    for (int c = 0; c < 3; ++c) coordinate[c] = c;
    return;
  }
  int n = 0;
  for (int c = 0; c < 3; ++c)
    if (v[c] != 0.0) coordinate[n++] = c;
  for (int c = 0; c < 3 && n < terms; ++c)
    if (v[c] == 0.0) coordinate[n++] = c;
}

}  // namespace

void QuadSet::put(std::size_t slot, const Quad& q) {
  Record& r = records_[slot];
  for (int axis = 0; axis < 3; ++axis) {
    r.normal[axis] = normal_[axis][slot] = q.plane_normal()[axis];
    r.axis_a[axis] = axis_a_[axis][slot] = q.axis_a()[axis];
    r.axis_b[axis] = axis_b_[axis][slot] = q.axis_b()[axis];
  }
  r.plane_offset = plane_offset_[slot] = q.plane_offset();
  r.offset_a = offset_a_[slot] = q.offset_a();
  r.offset_b = offset_b_[slot] = q.offset_b();
  r.parallel_threshold = parallel_threshold_[slot] = q.parallel_threshold();
  r.index = index_[slot] = static_cast<double>(size_++);
  const Vec3* vectors[3] = {&q.plane_normal(), &q.axis_a(), &q.axis_b()};
  int most = 0;
  for (const Vec3* v : vectors) most = std::max(most, nonzero_coordinates(*v));
  r.terms = most;
  for (int v = 0; v < 3; ++v) sum_coordinates(*vectors[v], r.terms, r.coordinate[v]);
}

// intersect_distance for every quad, chosen between with selects rather than early exits (a
// mispredicted branch costs more than the arithmetic it would skip).
QuadSet::Nearest QuadSet::nearest_portable(const Ray& ray, Interval range) const {
  Nearest best{size_, range.max};
  for (const Run& run : runs_)
    for (std::size_t k = 0; k < run.count; ++k) {
      const std::size_t s = run.begin + k;  // the slot of quad run.first + k
      const Vec3 n(normal_[0][s], normal_[1][s], normal_[2][s]);
      const Vec3 axis_a(axis_a_[0][s], axis_a_[1][s], axis_a_[2][s]);
      const Vec3 axis_b(axis_b_[0][s], axis_b_[1][s], axis_b_[2][s]);
      const double denom = glm::dot(n, ray.direction);
      const double t = (plane_offset_[s] - glm::dot(n, ray.origin)) / denom;
      const double a =
          (glm::dot(axis_a, ray.origin) - offset_a_[s]) + t * glm::dot(axis_a, ray.direction);
      const double b =
          (glm::dot(axis_b, ray.origin) - offset_b_[s]) + t * glm::dot(axis_b, ray.direction);
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
[[gnu::target("avx2")]] inline __m256d dot(const __m256d x[3], const __m256d y[3]) {
  return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(x[0], y[0]), _mm256_mul_pd(x[1], y[1])),
                       _mm256_mul_pd(x[2], y[2]));
}

// What intersect_distance computes before its tests, for four (quad, ray) pairs: n.d, t and
// the edge coordinates, with the same operations in the same order.
struct PlaneHits {
  __m256d denom, t, a, b;
};

// A quad's vectors and offsets, one quad per lane or one quad in every lane.
struct QuadLanes {
  __m256d normal[3], axis_a[3], axis_b[3];
  __m256d plane_offset, offset_a, offset_b;
};

[[gnu::target("avx2")]] inline PlaneHits plane_hits(const QuadLanes& q, const __m256d origin[3],
                                                    const __m256d direction[3]) {
  PlaneHits h;
  h.denom = dot(q.normal, direction);
  h.t = _mm256_div_pd(_mm256_sub_pd(q.plane_offset, dot(q.normal, origin)), h.denom);
  h.a = _mm256_add_pd(_mm256_sub_pd(dot(q.axis_a, origin), q.offset_a),
                      _mm256_mul_pd(h.t, dot(q.axis_a, direction)));
  h.b = _mm256_add_pd(_mm256_sub_pd(dot(q.axis_b, origin), q.offset_b),
                      _mm256_mul_pd(h.t, dot(q.axis_b, direction)));
  return h;
}

// x.v over the `Terms` coordinates of v that `coordinate` names, summed in glm::dot's order:
// with all three, glm::dot itself; with fewer, its sum without the products by zero. That
// value is the same (a sum of two terms does not depend on their order); only a zero sum may
// differ in its sign.
template <int Terms>
[[gnu::target("avx2")]] inline __m256d dot_of_terms(const double v[3],
                                                    const std::int32_t coordinate[3],
                                                    const __m256d x[3]) {
  __m256d sum = _mm256_mul_pd(_mm256_set1_pd(v[coordinate[0]]), x[coordinate[0]]);
  for (int k = 1; k < Terms; ++k)
    sum = _mm256_add_pd(sum, _mm256_mul_pd(_mm256_set1_pd(v[coordinate[k]]), x[coordinate[k]]));
  return sum;
}

// plane_hits for one quad in every lane, summing the products of its record's chosen
// coordinates (QuadSet::Record::terms).
template <int Terms, class Record>
[[gnu::target("avx2")]] inline PlaneHits plane_hits_of_terms(const Record& r, const __m256d o[3],
                                                             const __m256d d[3]) {
  PlaneHits h;
  h.denom = dot_of_terms<Terms>(r.normal, r.coordinate[0], d);
  h.t = _mm256_div_pd(_mm256_sub_pd(_mm256_set1_pd(r.plane_offset),
                                    dot_of_terms<Terms>(r.normal, r.coordinate[0], o)),
                      h.denom);
  h.a = _mm256_add_pd(_mm256_sub_pd(dot_of_terms<Terms>(r.axis_a, r.coordinate[1], o),
                                    _mm256_set1_pd(r.offset_a)),
                      _mm256_mul_pd(h.t, dot_of_terms<Terms>(r.axis_a, r.coordinate[1], d)));
  h.b = _mm256_add_pd(_mm256_sub_pd(dot_of_terms<Terms>(r.axis_b, r.coordinate[2], o),
                                    _mm256_set1_pd(r.offset_b)),
                      _mm256_mul_pd(h.t, dot_of_terms<Terms>(r.axis_b, r.coordinate[2], d)));
  return h;
}

// intersect_distance's tests on four (quad, ray) pairs, and the nearest kept: a lane takes t
// and the quad's index where the quad faces the ray (|n.d| not below the threshold), t is in
// (t_min, best_t) and (a, b) lies in [0,1]^2. Each comparison is NaN-safe in the same way as
// the plain one: !(|denom| < threshold), !(a < 0 || a > 1 || b < 0 || b > 1).
[[gnu::target("avx2")]] inline void keep_nearer(const PlaneHits& h, __m256d parallel_threshold,
                                                __m256d index, __m256d t_min, __m256d& best_t,
                                                __m256d& best_index) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const __m256d facing = _mm256_cmp_pd(_mm256_andnot_pd(_mm256_set1_pd(-0.0), h.denom),
                                       parallel_threshold, _CMP_NLT_UQ);
  const __m256d in_range =
      _mm256_and_pd(_mm256_cmp_pd(h.t, t_min, _CMP_GT_OQ), _mm256_cmp_pd(h.t, best_t, _CMP_LT_OQ));
  const __m256d inside = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(h.a, zero, _CMP_NLT_UQ),
                                                     _mm256_cmp_pd(h.a, one, _CMP_NGT_UQ)),
                                       _mm256_and_pd(_mm256_cmp_pd(h.b, zero, _CMP_NLT_UQ),
                                                     _mm256_cmp_pd(h.b, one, _CMP_NGT_UQ)));
  const __m256d closer = _mm256_and_pd(_mm256_and_pd(facing, in_range), inside);
  best_t = _mm256_blendv_pd(best_t, h.t, closer);
  best_index = _mm256_blendv_pd(best_index, index, closer);
}

// The slab test of four (ray, box) pairs, one per lane, with 1/d precomputed: bit l is set
// where lane l's ray o + t d, t in (t_min, t_max), meets lane l's box [low, high]. Where d has a
// zero coordinate, 1/d is infinite and the slab of that axis is all of t (o inside it) or none
// (o outside). An origin exactly on a face plane of the box, running in that plane, gives
// 0 x infinity = NaN: min and max (which return their second operand if either is NaN) then
// either drop that axis's limit or make the lane miss. Both are safe: such a ray stays the pad
// away from every quad of the group.
[[gnu::target("avx2")]] inline unsigned lanes_meeting_boxes(const __m256d low[3],
                                                            const __m256d high[3],
                                                            const __m256d origin[3],
                                                            const __m256d inverse_d[3],
                                                            __m256d t_min, __m256d t_max) {
  __m256d enter = t_min, leave = t_max;
  for (int axis = 0; axis < 3; ++axis) {
    const __m256d t_low = _mm256_mul_pd(_mm256_sub_pd(low[axis], origin[axis]), inverse_d[axis]);
    const __m256d t_high = _mm256_mul_pd(_mm256_sub_pd(high[axis], origin[axis]), inverse_d[axis]);
    enter = _mm256_max_pd(_mm256_min_pd(t_low, t_high), enter);
    leave = _mm256_min_pd(_mm256_max_pd(t_low, t_high), leave);
  }
  return static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(enter, leave, _CMP_LE_OQ)));
}

// Whether any of four rays meets box `b` of the boxes held coordinate by coordinate in `low`
// and `high` (the four-ray search's test of a group).
[[gnu::target("avx2")]] inline bool any_lane_meets_box(const std::vector<double> low[3],
                                                       const std::vector<double> high[3],
                                                       std::size_t b, const __m256d origin[3],
                                                       const __m256d inverse_d[3], __m256d t_min,
                                                       __m256d t_max) {
  const __m256d low_lanes[3] = {_mm256_set1_pd(low[0][b]), _mm256_set1_pd(low[1][b]),
                                _mm256_set1_pd(low[2][b])};
  const __m256d high_lanes[3] = {_mm256_set1_pd(high[0][b]), _mm256_set1_pd(high[1][b]),
                                 _mm256_set1_pd(high[2][b])};
  return lanes_meeting_boxes(low_lanes, high_lanes, origin, inverse_d, t_min, t_max) != 0;
}

}  // namespace

// The loop of nearest_portable on four quads per instruction, each lane keeping its own
// nearest t and index; the lanes are merged at the end (nearest t, then lowest index). Only
// AVX2 is enabled, not FMA: a fused multiply-add would round differently from the plain loop.
// A group is skipped when the ray misses its box before the nearest hit so far. The boxes are
// tested four at a time, when the first group of each four comes up: against the nearest hit
// as it was then, which is no nearer than when the later three come up, so no box that the
// ray meets before the nearest hit is missed (some it meets only beyond are tested in vain).
[[gnu::target("avx2")]] QuadSet::Nearest QuadSet::nearest_avx2(const Ray& ray,
                                                               Interval range) const {
  const __m256d origin[3] = {_mm256_set1_pd(ray.origin.x), _mm256_set1_pd(ray.origin.y),
                             _mm256_set1_pd(ray.origin.z)};
  const __m256d direction[3] = {_mm256_set1_pd(ray.direction.x), _mm256_set1_pd(ray.direction.y),
                                _mm256_set1_pd(ray.direction.z)};
  const __m256d t_min = _mm256_set1_pd(range.min), one = _mm256_set1_pd(1.0);
  const __m256d inverse_d[3] = {_mm256_div_pd(one, direction[0]), _mm256_div_pd(one, direction[1]),
                                _mm256_div_pd(one, direction[2])};
  __m256d best_t = _mm256_set1_pd(range.max);
  __m256d best_index = _mm256_set1_pd(-1.0);  // indices as doubles: exact below 2^53
  unsigned met = 0;  // of the four boxes last tested, those the ray meets (bit box % k_block)
  for (const Run& run : runs_) {
    if (run.bounded) {
      if (run.box % k_block == 0) {
        // Four boxes, one per lane, against the ray in every lane: lane by lane, the test
        // any_lane_meets_box makes of one box.
        const std::size_t b = run.box;
        const __m256d low[3] = {_mm256_loadu_pd(&box_low_[0][b]), _mm256_loadu_pd(&box_low_[1][b]),
                                _mm256_loadu_pd(&box_low_[2][b])};
        const __m256d high[3] = {_mm256_loadu_pd(&box_high_[0][b]),
                                 _mm256_loadu_pd(&box_high_[1][b]),
                                 _mm256_loadu_pd(&box_high_[2][b])};
        met = lanes_meeting_boxes(low, high, origin, inverse_d, t_min, avx2::all_lanes_min(best_t));
      }
      if ((met >> (run.box % k_block) & 1u) == 0) continue;
    }
    for (std::size_t i = run.begin; i < run.end; i += k_block) {
      QuadLanes q;
      for (int axis = 0; axis < 3; ++axis) {
        q.normal[axis] = _mm256_loadu_pd(&normal_[axis][i]);
        q.axis_a[axis] = _mm256_loadu_pd(&axis_a_[axis][i]);
        q.axis_b[axis] = _mm256_loadu_pd(&axis_b_[axis][i]);
      }
      q.plane_offset = _mm256_loadu_pd(&plane_offset_[i]);
      q.offset_a = _mm256_loadu_pd(&offset_a_[i]);
      q.offset_b = _mm256_loadu_pd(&offset_b_[i]);
      keep_nearer(plane_hits(q, origin, direction), _mm256_loadu_pd(&parallel_threshold_[i]),
                  _mm256_loadu_pd(&index_[i]), t_min, best_t, best_index);
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
//
// A quad whose vectors have coordinates that are zero is tested without their products in
// its dot products (Record::terms): for a box's walls, n.d becomes n_k d_k, and so on; for
// the sides of a box turned about an axis, two products instead of three. Adding the zero
// products changes a non-zero sum not at all, and a zero sum at most in its sign; for finite
// rays and t_min >= 0 no test can tell the two zeros apart (a zero n.d is never facing, a
// zero t never in range, a zero a or b is inside either way), so the answers keep every bit.
[[gnu::target("avx2")]] void QuadSet::nearest_lanes_avx2(const RayLanes& rays, double t_min,
                                                         NearestLanes& nearest) const {
  const __m256d origin[3] = {_mm256_load_pd(rays.origin_x), _mm256_load_pd(rays.origin_y),
                             _mm256_load_pd(rays.origin_z)};
  const __m256d direction[3] = {_mm256_load_pd(rays.direction_x), _mm256_load_pd(rays.direction_y),
                                _mm256_load_pd(rays.direction_z)};
  const __m256d t_low = _mm256_set1_pd(t_min), one = _mm256_set1_pd(1.0);
  __m256d best_t = _mm256_load_pd(nearest.t);
  __m256d best_index = _mm256_load_pd(nearest.index);
  const __m256d inverse_d[3] = {_mm256_div_pd(one, direction[0]), _mm256_div_pd(one, direction[1]),
                                _mm256_div_pd(one, direction[2])};
  for (const Run& run : runs_) {
    if (run.bounded &&
        !any_lane_meets_box(box_low_, box_high_, run.box, origin, inverse_d, t_low, best_t))
      continue;
    for (std::size_t i = run.begin; i < run.begin + run.count; ++i) {
      const Record& r = records_[i];
      PlaneHits h;
      switch (r.terms) {
        case 1: h = plane_hits_of_terms<1>(r, origin, direction); break;
        case 2: h = plane_hits_of_terms<2>(r, origin, direction); break;
        default: h = plane_hits_of_terms<3>(r, origin, direction);
      }
      keep_nearer(h, _mm256_set1_pd(r.parallel_threshold), _mm256_set1_pd(r.index), t_low, best_t,
                  best_index);
    }
  }
  _mm256_store_pd(nearest.t, best_t);
  _mm256_store_pd(nearest.index, best_index);
}

#else

QuadSet::Nearest QuadSet::nearest_avx2(const Ray& ray, Interval range) const {
  return nearest_portable(ray, range);
}

void QuadSet::nearest_lanes_avx2(const RayLanes& rays, double t_min, NearestLanes& nearest) const {
  nearest_lanes_portable(rays, t_min, nearest);
}

#endif

}  // namespace mcrt
