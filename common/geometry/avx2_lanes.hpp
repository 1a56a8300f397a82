#pragma once
/// What the four-wide searches of SphereSet and QuadSet share (x86 only): each lane keeps its
/// own nearest hit (t, and the primitive's index as a double, -1 for none), and at the end the
/// lanes are merged into the nearest hit overall, ties going to the lowest index, so the answer
/// is the portable loop's whatever lane a primitive fell in.

#if defined(__x86_64__) || defined(__i386__)
#define MCRT_X86 1
#include <immintrin.h>
#else
#define MCRT_X86 0
#endif

#if MCRT_X86

#include <limits>

namespace mcrt::avx2 {

/// The smallest of the four lanes, in every lane.
[[gnu::target("avx2")]] inline __m256d all_lanes_min(__m256d v) {
  v = _mm256_min_pd(v, _mm256_permute4x64_pd(v, 0x4e));  // halves swapped
  return _mm256_min_pd(v, _mm256_permute_pd(v, 0x5));    // neighbours swapped
}

/// The merged nearest hit: index < 0 when no lane hit.
struct NearestLane {
  double index;
  double t;
};

/// Merges the lanes without branches (they would mispredict): the nearest t into every lane,
/// then the lowest index among the lanes holding it. A lane that never hit holds index -1 and
/// t = the range's end, which a hit always beats; if no lane hit, the index is -1.
[[gnu::target("avx2")]] inline NearestLane merge_lanes(__m256d best_t, __m256d best_index) {
  const __m256d nearest_t = all_lanes_min(best_t);
  const __m256d holders = _mm256_cmp_pd(best_t, nearest_t, _CMP_EQ_OQ);
  const __m256d no_index = _mm256_set1_pd(std::numeric_limits<double>::infinity());
  return {_mm256_cvtsd_f64(all_lanes_min(_mm256_blendv_pd(no_index, best_index, holders))),
          _mm256_cvtsd_f64(nearest_t)};
}

}  // namespace mcrt::avx2

#endif
