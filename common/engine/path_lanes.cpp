#include "engine/path_lanes.hpp"

#include <array>

#include "core/cpu_features.hpp"

#if defined(__x86_64__)
#include <immintrin.h>

#include "core/pcg32_avx2.hpp"
#endif

namespace mcrt {

// ASSIGNMENT a4.1 BEGIN needs=a2.1 withheld stub: void shade_lanes(std::span<const Material>, int, PathLanes&, BounceLanes&) { NOT_IMPLEMENTED(shade_lanes); } void shade_lanes_portable(std::span<const Material>, int, PathLanes&, BounceLanes&) { NOT_IMPLEMENTED(shade_lanes_portable); } void shade_lanes_avx2(std::span<const Material>, int, PathLanes&, BounceLanes&) { NOT_IMPLEMENTED(shade_lanes_avx2); } unsigned end_lanes(PathLanes&, BounceLanes&) { NOT_IMPLEMENTED(end_lanes); } unsigned end_lanes_portable(PathLanes&, BounceLanes&) { NOT_IMPLEMENTED(end_lanes_portable); } unsigned end_lanes_avx2(PathLanes&, BounceLanes&) { NOT_IMPLEMENTED(end_lanes_avx2); }
void shade_lanes(std::span<const Material> materials, int max_depth, PathLanes& paths,
                 BounceLanes& bounce) {
  static const bool avx2 = cpu_has_avx2();
  if (avx2)
    shade_lanes_avx2(materials, max_depth, paths, bounce);
  else
    shade_lanes_portable(materials, max_depth, paths, bounce);
}

unsigned end_lanes(PathLanes& paths, BounceLanes& bounce) {
  static const bool avx2 = cpu_has_avx2();
  return avx2 ? end_lanes_avx2(paths, bounce) : end_lanes_portable(paths, bounce);
}

// The lines of estimate_path_radiance from the hit to the bounce's sample, lane by lane.
void shade_lanes_portable(std::span<const Material> materials, int max_depth, PathLanes& paths,
                          BounceLanes& bounce) {
  bounce.lobed = 0;
  for (int l = 0; l < PathLanes::k_lanes; ++l) {
    const Vec2 u = paths.uniform2(l);
    bounce.bouncing[l] = 0;
    if (paths.live[l] == 0 || !bounce.hit.found(l)) continue;
    const Material& material = materials[bounce.hit.material[l]];
    for (int axis = 0; axis < 3; ++axis)  // radiance += beta Le
      paths.radiance[axis][l] += bounce.beta[axis][l] * material.emission[axis];
    if (paths.depth[l] == max_depth) continue;
    bounce.bouncing[l] = -1;
    bounce.u0[l] = u.x;
    bounce.u1[l] = u.y;
    for (int axis = 0; axis < 3; ++axis) bounce.albedo[axis][l] = material.albedo[axis];
    if (material.has_lobe()) {
      bounce.lobed |= 1u << l;
      bounce.specular[l] = material.specular;
      bounce.exponent[l] = material.exponent;
    }
  }
}

// A black surface ends the path exactly: every later term would be multiplied by 0.
unsigned end_lanes_portable(PathLanes& paths, BounceLanes& bounce) {
  unsigned ended = 0;
  for (int l = 0; l < PathLanes::k_lanes; ++l) {
    const Color beta(bounce.beta[0][l], bounce.beta[1][l], bounce.beta[2][l]);
    if (bounce.bouncing[l] != 0 && beta != Color(0.0)) {
      ++paths.depth[l];
      continue;
    }
    if (paths.live[l] != 0) ended |= 1u << l;
    paths.depth[l] = 0;  // ready for a new path
    for (int axis = 0; axis < 3; ++axis) {
      paths.finished[axis][l] = paths.radiance[axis][l];
      paths.radiance[axis][l] = 0.0;
      bounce.beta[axis][l] = 1.0;
    }
  }
  return ended;
}

#if defined(__x86_64__)

namespace {

[[gnu::target("avx2")]] inline __m256i load_int(const std::int64_t* p) {
  return _mm256_load_si256(reinterpret_cast<const __m256i*>(p));
}
[[gnu::target("avx2")]] inline void store_int(std::int64_t* p, __m256i v) {
  _mm256_store_si256(reinterpret_cast<__m256i*>(p), v);
}
[[gnu::target("avx2")]] inline __m256i lanes_of(const std::array<std::uint64_t, 4>& v) {
  return _mm256_setr_epi64x(static_cast<long long>(v[0]), static_cast<long long>(v[1]),
                            static_cast<long long>(v[2]), static_cast<long long>(v[3]));
}
[[gnu::target("avx2")]] inline __m256d as_double(__m256i v) { return _mm256_castsi256_pd(v); }

}  // namespace

[[gnu::target("avx2")]] void shade_lanes_avx2(std::span<const Material> materials, int max_depth,
                                              PathLanes& paths, BounceLanes& bounce) {
  // The two uniforms of every lane: u0 from the state s0, u1 from s1 = a s0 + c; s2 = a s1 + c.
  const avx2::Pcg32Multiplier a = avx2::pcg32_multiplier(k_pcg32_multiplier);
  // The generators are read lane by lane: a path's start writes them one lane at a time, and a
  // 32-byte load of four such stores would wait for them to reach the cache.
  const __m256i c = lanes_of(paths.rng.increment);
  const __m256i s0 = lanes_of(paths.rng.state);
  const __m256i s1 = avx2::pcg32_lcg(s0, _mm256_srli_epi64(s0, 32), a, c);
  const __m256i s2 = avx2::pcg32_lcg(s1, _mm256_srli_epi64(s1, 32), a, c);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(paths.rng.state.data()), s2);

  // Live lanes whose ray hit (material >= 0), and those of them that bounce.
  const __m256i material = load_int(bounce.hit.material);
  const __m256i shaded =
      _mm256_and_si256(load_int(paths.live), _mm256_cmpgt_epi64(material, _mm256_set1_epi64x(-1)));
  const __m256i at_cut = _mm256_cmpeq_epi64(load_int(paths.depth), _mm256_set1_epi64x(max_depth));
  const __m256i bouncing = _mm256_andnot_si256(at_cut, shaded);
  store_int(bounce.bouncing, bouncing);

  // Each lane's material, read lane by lane (on some processors a gather costs more); a lane
  // that missed reads a black one, and its radiance is left as it was.
  static const Material none;
  const Material* of[PathLanes::k_lanes];
  for (int l = 0; l < PathLanes::k_lanes; ++l)
    of[l] =
        bounce.hit.found(l) ? &materials[static_cast<std::size_t>(bounce.hit.material[l])] : &none;
  const __m256d shaded_mask = as_double(shaded);
  for (int axis = 0; axis < 3; ++axis) {
    const __m256d emission = _mm256_setr_pd(of[0]->emission[axis], of[1]->emission[axis],
                                            of[2]->emission[axis], of[3]->emission[axis]);
    const __m256d radiance = _mm256_load_pd(paths.radiance[axis]);
    const __m256d added =
        _mm256_add_pd(radiance, _mm256_mul_pd(_mm256_load_pd(bounce.beta[axis]), emission));
    _mm256_store_pd(paths.radiance[axis], _mm256_blendv_pd(radiance, added, shaded_mask));
    _mm256_store_pd(bounce.albedo[axis], _mm256_setr_pd(of[0]->albedo[axis], of[1]->albedo[axis],
                                                        of[2]->albedo[axis], of[3]->albedo[axis]));
  }
  // Lanes that bounce off a glossy lobe: bounce_lanes weighs them one at a time. In a
  // diffuse scene (lobes_possible false) `lobed` stays 0 and nothing is looked at.
  if (bounce.lobes_possible) {
    const unsigned lobed = static_cast<unsigned>(of[0]->has_lobe()) |
                           static_cast<unsigned>(of[1]->has_lobe()) << 1 |
                           static_cast<unsigned>(of[2]->has_lobe()) << 2 |
                           static_cast<unsigned>(of[3]->has_lobe()) << 3;
    for (int l = 0; l < PathLanes::k_lanes; ++l) {
      bounce.specular[l] = of[l]->specular;
      bounce.exponent[l] = of[l]->exponent;
    }
    bounce.lobed = lobed & static_cast<unsigned>(_mm256_movemask_pd(as_double(bouncing)));
  }
  _mm256_store_pd(bounce.u0, avx2::pcg32_uniform(avx2::pcg32_output(s0)));
  _mm256_store_pd(bounce.u1, avx2::pcg32_uniform(avx2::pcg32_output(s1)));
}

[[gnu::target("avx2")]] unsigned end_lanes_avx2(PathLanes& paths, BounceLanes& bounce) {
  // beta != 0 in some axis; NaN counts as not black, as in Color's !=.
  __m256d not_black = _mm256_setzero_pd();
  for (int axis = 0; axis < 3; ++axis)
    not_black = _mm256_or_pd(not_black, _mm256_cmp_pd(_mm256_load_pd(bounce.beta[axis]),
                                                      _mm256_setzero_pd(), _CMP_NEQ_UQ));
  const __m256i going_on =
      _mm256_and_si256(load_int(bounce.bouncing), _mm256_castpd_si256(not_black));
  // depth + 1 where the path goes on (- (-1)), 0 elsewhere; the others made ready likewise.
  store_int(paths.depth,
            _mm256_and_si256(going_on, _mm256_sub_epi64(load_int(paths.depth), going_on)));
  const __m256d kept = as_double(going_on);
  for (int axis = 0; axis < 3; ++axis) {
    const __m256d radiance = _mm256_load_pd(paths.radiance[axis]);
    _mm256_store_pd(paths.finished[axis], radiance);
    _mm256_store_pd(paths.radiance[axis], _mm256_and_pd(radiance, kept));
    _mm256_store_pd(bounce.beta[axis],
                    _mm256_blendv_pd(_mm256_set1_pd(1.0), _mm256_load_pd(bounce.beta[axis]), kept));
  }
  const __m256i ended = _mm256_andnot_si256(going_on, load_int(paths.live));
  return static_cast<unsigned>(_mm256_movemask_pd(as_double(ended)));
}

#else

void shade_lanes_avx2(std::span<const Material> materials, int max_depth, PathLanes& paths,
                      BounceLanes& bounce) {
  shade_lanes_portable(materials, max_depth, paths, bounce);
}
unsigned end_lanes_avx2(PathLanes& paths, BounceLanes& bounce) {
  return end_lanes_portable(paths, bounce);
}

#endif

// ASSIGNMENT a4.1 END

}  // namespace mcrt
