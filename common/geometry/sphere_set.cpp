#include "geometry/sphere_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/avx2_lanes.hpp"

namespace mcrt {

namespace {

// sqrt of a non-negative number as one instruction: std::sqrt must also set errno for negative
// input, and the branch that checks for it mispredicts as often as rays miss spheres.
inline double sqrt_non_negative(double x) {
#if MCRT_X86
  return _mm_cvtsd_f64(_mm_sqrt_sd(_mm_setzero_pd(), _mm_set_sd(x)));
#else
  return std::sqrt(x);
#endif
}

}  // namespace

void SphereSet::add(const Sphere& s) {
  // Fill the first padding slot if there is one, else open a new block of padding.
  if (size_ == center_x_.size()) {
    center_x_.resize(size_ + k_block, 0.0);
    center_y_.resize(size_ + k_block, 0.0);
    center_z_.resize(size_ + k_block, 0.0);
    // det = b^2 - |c - o|^2 + r^2 = -infinity < 0: a padding sphere is never hit.
    radius_squared_.resize(size_ + k_block, -std::numeric_limits<double>::infinity());
  }
  center_x_[size_] = s.center.x;
  center_y_[size_] = s.center.y;
  center_z_[size_] = s.center.z;
  radius_squared_[size_] = s.radius * s.radius;
  inverse_radius_.push_back(1.0 / s.radius);
  ++size_;
}

// Both roots of every sphere, chosen between with selects rather than early exits (a
// mispredicted branch costs more than the square root it would skip); it keeps the first root
// beyond range.min: the same t, bit for bit, as intersect_distance.
SphereSet::Nearest SphereSet::nearest_portable(const Ray& ray, Interval range) const {
  Nearest best{size_, range.max};
  for (std::size_t i = 0; i < size_; ++i) {
    const Vec3 oc = Vec3(center_x_[i], center_y_[i], center_z_[i]) - ray.origin;
    const double b = glm::dot(oc, ray.direction);
    const double det = b * b - glm::dot(oc, oc) + radius_squared_[i];
    const double root = sqrt_non_negative(std::max(det, 0.0));
    const double near = b - root, far = b + root;
    const double t = near > range.min ? near : far;
    const bool closer = det >= 0.0 && t > range.min && t < best.t;
    best.t = closer ? t : best.t;
    best.index = closer ? i : best.index;
  }
  return best;
}

void SphereSet::nearest_lanes_portable(const RayLanes& rays, double t_min,
                                       NearestLanes& nearest) const {
  for (int l = 0; l < RayLanes::k_lanes; ++l) {
    const Nearest best = nearest_portable(rays.get(l), {t_min, nearest.t[l]});
    if (best.index == size_) continue;
    nearest.t[l] = best.t;
    nearest.index[l] = static_cast<double>(best.index);
  }
}

#if MCRT_X86

// The loop of nearest_portable on four spheres per instruction, each lane keeping its own
// nearest t and index; the lanes are merged at the end (nearest t, then lowest index). Only
// AVX2 is enabled, not FMA: a fused multiply-add would round differently from the portable
// loop. 2.0x the closest-hit queries per second of the one-at-a-time loop on cornell-spheres
// (bench_path_tracer).
[[gnu::target("avx2")]] SphereSet::Nearest SphereSet::nearest_avx2(const Ray& ray,
                                                                   Interval range) const {
  const __m256d ox = _mm256_set1_pd(ray.origin.x), oy = _mm256_set1_pd(ray.origin.y),
                oz = _mm256_set1_pd(ray.origin.z);
  const __m256d dx = _mm256_set1_pd(ray.direction.x), dy = _mm256_set1_pd(ray.direction.y),
                dz = _mm256_set1_pd(ray.direction.z);
  const __m256d t_min = _mm256_set1_pd(range.min), zero = _mm256_setzero_pd();
  const __m256d step = _mm256_set1_pd(static_cast<double>(k_block));
  __m256d best_t = _mm256_set1_pd(range.max);
  __m256d best_index = _mm256_set1_pd(-1.0);  // indices as doubles: exact below 2^53
  __m256d index = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
  for (std::size_t i = 0; i < center_x_.size(); i += k_block) {
    const __m256d ocx = _mm256_sub_pd(_mm256_loadu_pd(&center_x_[i]), ox);
    const __m256d ocy = _mm256_sub_pd(_mm256_loadu_pd(&center_y_[i]), oy);
    const __m256d ocz = _mm256_sub_pd(_mm256_loadu_pd(&center_z_[i]), oz);
    // b = oc.d and |oc|^2, summed x + y, then + z, as glm::dot does.
    const __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ocx, dx), _mm256_mul_pd(ocy, dy)),
                                    _mm256_mul_pd(ocz, dz));
    const __m256d oc2 =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ocx, ocx), _mm256_mul_pd(ocy, ocy)),
                      _mm256_mul_pd(ocz, ocz));
    const __m256d det = _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(b, b), oc2),
                                      _mm256_loadu_pd(&radius_squared_[i]));
    const __m256d root = _mm256_sqrt_pd(_mm256_max_pd(det, zero));
    const __m256d near = _mm256_sub_pd(b, root), far = _mm256_add_pd(b, root);
    const __m256d t = _mm256_blendv_pd(far, near, _mm256_cmp_pd(near, t_min, _CMP_GT_OQ));
    const __m256d closer = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(det, zero, _CMP_GE_OQ),
                                                       _mm256_cmp_pd(t, t_min, _CMP_GT_OQ)),
                                         _mm256_cmp_pd(t, best_t, _CMP_LT_OQ));
    best_t = _mm256_blendv_pd(best_t, t, closer);
    best_index = _mm256_blendv_pd(best_index, index, closer);
    index = _mm256_add_pd(index, step);
  }
  const avx2::NearestLane nearest = avx2::merge_lanes(best_t, best_index);
  if (nearest.index < 0.0) return {size_, range.max};
  return {static_cast<std::size_t>(nearest.index), nearest.t};
}

// nearest_portable's loop body with one sphere broadcast to the four lanes and a ray in each:
// every lane does what the one-ray loop does, in the same order, so no lanes are merged at
// the end. The padding spheres are skipped: only the first size() are read.
[[gnu::target("avx2")]] void SphereSet::nearest_lanes_avx2(const RayLanes& rays, double t_min,
                                                           NearestLanes& nearest) const {
  const __m256d ox = _mm256_load_pd(rays.origin_x), oy = _mm256_load_pd(rays.origin_y),
                oz = _mm256_load_pd(rays.origin_z);
  const __m256d dx = _mm256_load_pd(rays.direction_x), dy = _mm256_load_pd(rays.direction_y),
                dz = _mm256_load_pd(rays.direction_z);
  const __m256d t_low = _mm256_set1_pd(t_min), zero = _mm256_setzero_pd();
  __m256d best_t = _mm256_load_pd(nearest.t);
  __m256d best_index = _mm256_load_pd(nearest.index);
  for (std::size_t i = 0; i < size_; ++i) {
    const __m256d ocx = _mm256_sub_pd(_mm256_set1_pd(center_x_[i]), ox);
    const __m256d ocy = _mm256_sub_pd(_mm256_set1_pd(center_y_[i]), oy);
    const __m256d ocz = _mm256_sub_pd(_mm256_set1_pd(center_z_[i]), oz);
    const __m256d b = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ocx, dx), _mm256_mul_pd(ocy, dy)),
                                    _mm256_mul_pd(ocz, dz));
    const __m256d oc2 =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ocx, ocx), _mm256_mul_pd(ocy, ocy)),
                      _mm256_mul_pd(ocz, ocz));
    const __m256d det =
        _mm256_add_pd(_mm256_sub_pd(_mm256_mul_pd(b, b), oc2), _mm256_set1_pd(radius_squared_[i]));
    const __m256d root = _mm256_sqrt_pd(_mm256_max_pd(det, zero));
    const __m256d near = _mm256_sub_pd(b, root), far = _mm256_add_pd(b, root);
    const __m256d t = _mm256_blendv_pd(far, near, _mm256_cmp_pd(near, t_low, _CMP_GT_OQ));
    const __m256d closer = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(det, zero, _CMP_GE_OQ),
                                                       _mm256_cmp_pd(t, t_low, _CMP_GT_OQ)),
                                         _mm256_cmp_pd(t, best_t, _CMP_LT_OQ));
    best_t = _mm256_blendv_pd(best_t, t, closer);
    best_index = _mm256_blendv_pd(best_index, _mm256_set1_pd(static_cast<double>(i)), closer);
  }
  _mm256_store_pd(nearest.t, best_t);
  _mm256_store_pd(nearest.index, best_index);
}

#else

SphereSet::Nearest SphereSet::nearest_avx2(const Ray& ray, Interval range) const {
  return nearest_portable(ray, range);
}

void SphereSet::nearest_lanes_avx2(const RayLanes& rays, double t_min,
                                   NearestLanes& nearest) const {
  nearest_lanes_portable(rays, t_min, nearest);
}

#endif

}  // namespace mcrt
