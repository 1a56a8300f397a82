#include "geometry/quad_set.hpp"

#include <cmath>
#include <limits>

#include "core/cpu_features.hpp"
#include "geometry/avx2_lanes.hpp"

namespace mcrt {

const bool QuadSet::k_has_avx2 = cpu_has_avx2();

void QuadSet::add(const Quad& q) {
  // Fill the first padding slot if there is one, else open a new block of padding.
  if (size_ == normal_x_.size()) {
    for (std::vector<double>* v : {&normal_x_, &normal_y_, &normal_z_, &corner_x_, &corner_y_,
                                   &corner_z_, &axis_a_x_, &axis_a_y_, &axis_a_z_, &axis_b_x_,
                                   &axis_b_y_, &axis_b_z_})
      v->resize(size_ + k_block, 0.0);
    // |n.d| < +infinity always: a padding quad is never hit.
    parallel_threshold_.resize(size_ + k_block, std::numeric_limits<double>::infinity());
  }
  normal_x_[size_] = q.plane_normal().x;
  normal_y_[size_] = q.plane_normal().y;
  normal_z_[size_] = q.plane_normal().z;
  corner_x_[size_] = q.corner().x;
  corner_y_[size_] = q.corner().y;
  corner_z_[size_] = q.corner().z;
  axis_a_x_[size_] = q.axis_a().x;
  axis_a_y_[size_] = q.axis_a().y;
  axis_a_z_[size_] = q.axis_a().z;
  axis_b_x_[size_] = q.axis_b().x;
  axis_b_y_[size_] = q.axis_b().y;
  axis_b_z_[size_] = q.axis_b().z;
  parallel_threshold_[size_] = q.parallel_threshold();
  ++size_;
}

// intersect_distance for every quad, chosen between with selects rather than early exits (a
// mispredicted branch costs more than the arithmetic it would skip).
QuadSet::Nearest QuadSet::nearest_portable(const Ray& ray, Interval range) const {
  Nearest best{size_, range.max};
  for (std::size_t i = 0; i < size_; ++i) {
    const Vec3 n(normal_x_[i], normal_y_[i], normal_z_[i]);
    const Vec3 corner(corner_x_[i], corner_y_[i], corner_z_[i]);
    const double denom = glm::dot(n, ray.direction);
    const double t = glm::dot(n, corner - ray.origin) / denom;
    const Vec3 p = ray.at(t) - corner;
    const double a = glm::dot(p, Vec3(axis_a_x_[i], axis_a_y_[i], axis_a_z_[i]));
    const double b = glm::dot(p, Vec3(axis_b_x_[i], axis_b_y_[i], axis_b_z_[i]));
    const bool closer = !(std::abs(denom) < parallel_threshold_[i]) && t > range.min &&
                        t < best.t && !(a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0);
    best.t = closer ? t : best.t;
    best.index = closer ? i : best.index;
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

}  // namespace

// The loop of nearest_portable on four quads per instruction, each lane keeping its own
// nearest t and index; the lanes are merged at the end (nearest t, then lowest index). Only
// AVX2 is enabled, not FMA: a fused multiply-add would round differently from the plain loop.
[[gnu::target("avx2")]] QuadSet::Nearest QuadSet::nearest_avx2(const Ray& ray,
                                                               Interval range) const {
  const __m256d ox = _mm256_set1_pd(ray.origin.x), oy = _mm256_set1_pd(ray.origin.y),
                oz = _mm256_set1_pd(ray.origin.z);
  const __m256d dx = _mm256_set1_pd(ray.direction.x), dy = _mm256_set1_pd(ray.direction.y),
                dz = _mm256_set1_pd(ray.direction.z);
  const __m256d t_min = _mm256_set1_pd(range.min), zero = _mm256_setzero_pd(),
                one = _mm256_set1_pd(1.0), sign = _mm256_set1_pd(-0.0);
  const __m256d step = _mm256_set1_pd(static_cast<double>(k_block));
  __m256d best_t = _mm256_set1_pd(range.max);
  __m256d best_index = _mm256_set1_pd(-1.0);  // indices as doubles: exact below 2^53
  __m256d index = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
  for (std::size_t i = 0; i < normal_x_.size(); i += k_block) {
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
    best_index = _mm256_blendv_pd(best_index, index, closer);
    index = _mm256_add_pd(index, step);
  }
  const avx2::NearestLane nearest = avx2::merge_lanes(best_t, best_index);
  if (nearest.index < 0.0) return {size_, range.max};
  return {static_cast<std::size_t>(nearest.index), nearest.t};
}

// nearest_portable's loop body with one quad broadcast to the four lanes and a ray in each:
// every lane does what the one-ray loop does, in the same order, so no lanes are merged at
// the end. The padding quads are skipped: only the first size() are read.
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
  for (std::size_t i = 0; i < size_; ++i) {
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
    best_index = _mm256_blendv_pd(best_index, _mm256_set1_pd(static_cast<double>(i)), closer);
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
