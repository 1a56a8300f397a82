#include "engine/path_starts.hpp"

#include "core/cpu_features.hpp"
#include "core/pcg32_lanes.hpp"
#include "core/rng.hpp"

#if defined(__x86_64__)
#include <immintrin.h>

#include "core/pcg32_avx2.hpp"
#endif

namespace mcrt {

void make_path_starts(const Camera& camera, const RenderSettings& settings, int y, RowSample& next,
                      int count, PathStarts& starts) {
  static const bool avx2 = cpu_has_avx2();
  if (avx2)
    make_path_starts_avx2(camera, settings, y, next, count, starts);
  else
    make_path_starts_portable(camera, settings, y, next, count, starts);
}

// render()'s two lines, one sample at a time: Pcg32Lanes<1> is Rng's engine with its state in
// view.
void make_path_starts_portable(const Camera& camera, const RenderSettings& settings, int y,
                               RowSample& next, int count, PathStarts& starts) {
  const std::uint64_t row = static_cast<std::uint64_t>(y) * camera.width();
  for (int i = 0; i < count; ++i, next.advance(settings.spp)) {
    const std::uint64_t stream = stream_index(row + next.x, settings.first_sample + next.sample);
    Pcg32Lanes<1> rng;
    rng.seed_lane(0, Rng::starting_state(settings.seed, stream), stream);
    const double u0 = rng.next(0) * 0x1p-32;  // Rng::uniform2's order: u0 first
    const Ray ray = camera.generate_ray(next.x, y, {u0, rng.next(0) * 0x1p-32});
    starts.state[i] = rng.state[0];
    starts.increment[i] = rng.increment[0];
    for (int axis = 0; axis < 3; ++axis) {
      starts.origin[axis][i] = ray.origin[axis];
      starts.direction[axis][i] = ray.direction[axis];
    }
  }
}

#if defined(__x86_64__)

namespace {

// z m (mod 2^64) in each 64-bit lane.
[[gnu::target("avx2")]] inline __m256i times(__m256i z, avx2::Pcg32Multiplier m) {
  return avx2::pcg32_lcg(z, _mm256_srli_epi64(z, 32), m, _mm256_setzero_si256());
}

// s a + c (mod 2^64): PCG32's step.
[[gnu::target("avx2")]] inline __m256i step(__m256i s, avx2::Pcg32Multiplier a, __m256i c) {
  return avx2::pcg32_lcg(s, _mm256_srli_epi64(s, 32), a, c);
}

// core/rng.hpp's mix64 in each lane.
[[gnu::target("avx2")]] inline __m256i mix64(__m256i z) {
  const avx2::Pcg32Multiplier m1 = avx2::pcg32_multiplier(k_mix64_first);
  const avx2::Pcg32Multiplier m2 = avx2::pcg32_multiplier(k_mix64_second);
  z = times(_mm256_xor_si256(z, _mm256_srli_epi64(z, 30)), m1);
  z = times(_mm256_xor_si256(z, _mm256_srli_epi64(z, 27)), m2);
  return _mm256_xor_si256(z, _mm256_srli_epi64(z, 31));
}

[[gnu::target("avx2")]] inline __m256d set(double v) { return _mm256_set1_pd(v); }

}  // namespace

// Four samples per pass. The last pass may make up to three starts past `count`, from the
// samples after them; they are never read.
[[gnu::target("avx2")]] void make_path_starts_avx2(const Camera& camera,
                                                   const RenderSettings& settings, int y,
                                                   RowSample& next, int count, PathStarts& starts) {
  const avx2::Pcg32Multiplier a = avx2::pcg32_multiplier(k_pcg32_multiplier);
  const Camera::Frame frame = camera.frame();
  const std::uint64_t row = static_cast<std::uint64_t>(y) * camera.width();
  for (int i = 0; i < count; i += 4) {
    alignas(32) std::uint64_t stream[4];
    alignas(32) double x[4];
    RowSample sample = next;
    for (int l = 0; l < 4; ++l, sample.advance(settings.spp)) {
      if (i + l < count) next.advance(settings.spp);
      stream[l] = stream_index(row + sample.x, settings.first_sample + sample.sample);
      x[l] = sample.x;
    }
    // Rng(seed, stream): its starting state, then pcg32's seeding, c = 2 stream + 1 and
    // s0 = (starting state + c) a + c; the two draws read s0 and s1 and leave s2.
    const __m256i streams = _mm256_load_si256(reinterpret_cast<const __m256i*>(stream));
    const __m256i golden = _mm256_set1_epi64x(static_cast<long long>(k_stream_offset));
    const __m256i seed = _mm256_set1_epi64x(static_cast<long long>(settings.seed));
    const __m256i starting =
        mix64(_mm256_xor_si256(seed, mix64(_mm256_add_epi64(streams, golden))));
    const __m256i c = _mm256_or_si256(_mm256_slli_epi64(streams, 1), _mm256_set1_epi64x(1));
    const __m256i s0 = step(_mm256_add_epi64(starting, c), a, c);
    const __m256i s1 = step(s0, a, c);
    _mm256_store_si256(reinterpret_cast<__m256i*>(starts.state + i), step(s1, a, c));
    _mm256_store_si256(reinterpret_cast<__m256i*>(starts.increment + i), c);
    const __m256d u0 = avx2::pcg32_uniform(avx2::pcg32_output(s0));
    const __m256d u1 = avx2::pcg32_uniform(avx2::pcg32_output(s1));

    // Camera::generate_ray(x + u0, y + u1): d = forward + (px/w - 1/2) right + (1/2 - py/h) up,
    // direction = d (1 / sqrt(d.d)) as glm::normalize computes it, origin = eye + near direction.
    const __m256d px = _mm256_add_pd(_mm256_load_pd(x), u0);
    const __m256d py = _mm256_add_pd(set(y), u1);
    const __m256d along_right = _mm256_sub_pd(_mm256_div_pd(px, set(camera.width())), set(0.5));
    const __m256d along_up = _mm256_sub_pd(set(0.5), _mm256_div_pd(py, set(camera.height())));
    __m256d d[3];
    for (int axis = 0; axis < 3; ++axis)
      d[axis] = _mm256_add_pd(_mm256_add_pd(set(frame.forward[axis]),
                                            _mm256_mul_pd(along_right, set(frame.right[axis]))),
                              _mm256_mul_pd(along_up, set(frame.up[axis])));
    const __m256d length_squared =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(d[0], d[0]), _mm256_mul_pd(d[1], d[1])),
                      _mm256_mul_pd(d[2], d[2]));
    const __m256d inverse_length = _mm256_div_pd(set(1.0), _mm256_sqrt_pd(length_squared));
    for (int axis = 0; axis < 3; ++axis) {
      const __m256d direction = _mm256_mul_pd(d[axis], inverse_length);
      _mm256_store_pd(starts.origin[axis] + i,
                      _mm256_add_pd(set(frame.eye[axis]),
                                    _mm256_mul_pd(set(frame.near), direction)));
      _mm256_store_pd(starts.direction[axis] + i, direction);
    }
  }
}

#else

void make_path_starts_avx2(const Camera& camera, const RenderSettings& settings, int y,
                           RowSample& next, int count, PathStarts& starts) {
  make_path_starts_portable(camera, settings, y, next, count, starts);
}

#endif

}  // namespace mcrt
