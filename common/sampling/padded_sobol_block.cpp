#include "sampling/padded_sobol_block.hpp"

#include <algorithm>

#if defined(__x86_64__)
// GCC 12's AVX-512 intrinsics start many results from an "undefined" register that -Wall
// reports as uninitialised (GCC bug 105593, fixed in GCC 13): silenced for this file only.
#if !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <immintrin.h>
#endif

#include "core/cpu_features.hpp"

namespace mcrt {

namespace {

// The plain steps, lane by lane in loops the compiler turns into vector code: one shuffle
// pass for every lane, the rare extra passes (cycle walking) one lane at a time, then the
// scrambles and the conversion. Inlined into the portable and the AVX2 copies below.
[[gnu::always_inline]] inline void make_block(const PaddedSetKeys& keys, std::uint32_t first,
                                              std::uint32_t count, unsigned h,
                                              std::array<Vec2, k_sobol_block>& points) {
  std::uint32_t p[k_sobol_block];
  // The pass and the test for walking in loops of their own: a test folded into the pass's loop
  // kept GCC from vectorising the pass.
  for (unsigned i = 0; i < k_sobol_block; ++i) p[i] = shuffle_pass(first + i, h, keys);
  std::uint32_t largest = 0;
  for (unsigned i = 0; i < k_sobol_block; ++i) largest = std::max(largest, p[i]);
  if (largest >= count)
    for (unsigned i = 0; i < k_sobol_block && first + i < count; ++i) {
      if (count <= 1) p[i] = 0;
      while (p[i] >= count) p[i] = shuffle_pass(p[i], h, keys);
    }
  for (unsigned i = 0; i < k_sobol_block; ++i) {
    const std::uint32_t x_bits = reverse_bits(laine_karras_permutation(p[i], keys.seed_x));
    const std::uint32_t y_bits =
        reverse_bits(laine_karras_permutation(sobol_dimension1_reversed(p[i]), keys.seed_y));
    points[i] = padded_point_from_bits(x_bits, y_bits, keys.key, first + i);
  }
}

#if defined(__x86_64__)
// The AVX-512 block, written in intrinsics: the compiler left the shuffle's rounds scalar at
// this width, and has no instruction for reverse_bits. Each helper is a step of
// padded_sobol_point for sixteen lanes at once.
#define MCRT_AVX512 gnu::target("avx512f,avx512bw,avx512vl,avx512dq"), gnu::always_inline

/// The shuffle's round functions, broadcast once per block.
struct ShuffleRounds16 {
  __m512i a[3], b[3], mask;
  __m128i h, rest;  // shift counts h and 32 - h
};

/// shuffle_pass in every lane.
[[MCRT_AVX512]] inline __m512i shuffle_pass16(__m512i x, const ShuffleRounds16& rounds) {
  __m512i left = _mm512_srl_epi32(x, rounds.h);
  __m512i right = _mm512_and_si512(x, rounds.mask);
  for (unsigned r = 0; r < 3; ++r) {
    const __m512i product = _mm512_add_epi32(_mm512_mullo_epi32(rounds.a[r], right), rounds.b[r]);
    const __m512i next = _mm512_xor_si512(left, _mm512_srl_epi32(product, rounds.rest));
    left = right;
    right = next;
  }
  return _mm512_or_si512(_mm512_sll_epi32(left, rounds.h), right);
}

/// laine_karras_permutation in every lane.
[[MCRT_AVX512]] inline __m512i laine_karras16(__m512i x, std::uint32_t seed) {
  x = _mm512_add_epi32(x, _mm512_set1_epi32(static_cast<int>(seed)));
  for (const std::uint32_t multiplier : {0x6c50b47cu, 0xb82f1e52u, 0xc7afe638u, 0x8d22f6e6u})
    x = _mm512_xor_si512(x, _mm512_mullo_epi32(x, _mm512_set1_epi32(static_cast<int>(multiplier))));
  return x;
}

/// x ^ ((x >> shift) & mask) in every lane: one step of sobol_dimension1_reversed. The
/// ternary-logic immediate 0x78 is A ^ (B & C) (A = 0xf0, B = 0xcc, C = 0xaa).
[[MCRT_AVX512]] inline __m512i xor_shifted16(__m512i x, unsigned shift, std::uint32_t mask) {
  return _mm512_ternarylogic_epi32(x, _mm512_srli_epi32(x, shift),
                                   _mm512_set1_epi32(static_cast<int>(mask)), 0x78);
}

/// reverse_bits in every lane: each byte's two nibbles reversed by a 16-entry table and
/// swapped, then the four bytes of each word in reverse order.
[[MCRT_AVX512]] inline __m512i reverse_bits16(__m512i x) {
  const __m512i nibble_reversed =
      _mm512_broadcast_i32x4(_mm_setr_epi8(0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5,
                                           0xd, 0x3, 0xb, 0x7, 0xf));
  const __m512i bytes_reversed =
      _mm512_broadcast_i32x4(_mm_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12));
  const __m512i low_nibble = _mm512_set1_epi8(0x0f);
  const __m512i low = _mm512_shuffle_epi8(nibble_reversed, _mm512_and_si512(x, low_nibble));
  const __m512i high =
      _mm512_shuffle_epi8(nibble_reversed, _mm512_and_si512(_mm512_srli_epi16(x, 4), low_nibble));
  return _mm512_shuffle_epi8(_mm512_or_si512(_mm512_slli_epi16(low, 4), high), bytes_reversed);
}

/// Eight lanes' points of padded_point_from_bits: coordinates x_bits, y_bits and their fill
/// (low_x, low_y), (bits + low * 2^-32) * 2^-32, with one rounding as in the plain version,
/// stored as (x, y) pairs.
[[MCRT_AVX512]] inline void store_points8(__m256i x_bits, __m256i y_bits, __m256i low_x,
                                          __m256i low_y, Vec2* out) {
  const __m512d scale = _mm512_set1_pd(0x1p-32);
  const __m512d x =
      _mm512_mul_pd(_mm512_fmadd_pd(_mm512_cvtepu32_pd(low_x), scale, _mm512_cvtepu32_pd(x_bits)),
                    scale);
  const __m512d y =
      _mm512_mul_pd(_mm512_fmadd_pd(_mm512_cvtepu32_pd(low_y), scale, _mm512_cvtepu32_pd(y_bits)),
                    scale);
  const __m512i first_pairs = _mm512_setr_epi64(0, 8, 1, 9, 2, 10, 3, 11);
  const __m512i last_pairs = _mm512_setr_epi64(4, 12, 5, 13, 6, 14, 7, 15);
  static_assert(sizeof(Vec2) == 2 * sizeof(double));
  double* pairs = reinterpret_cast<double*>(out);
  _mm512_storeu_pd(pairs, _mm512_permutex2var_pd(x, first_pairs, y));
  _mm512_storeu_pd(pairs + 8, _mm512_permutex2var_pd(x, last_pairs, y));
}

/// The fill of eight lanes (padded_point_from_bits): (key ^ index) * k_mix64_first, xorshifted
/// by 29; low_x is each word's high half, low_y its low half.
[[MCRT_AVX512]] inline void fill_bits8(__m256i index, std::uint64_t key, __m256i& low_x,
                                       __m256i& low_y) {
  __m512i bits =
      _mm512_mullo_epi64(_mm512_xor_si512(_mm512_cvtepu32_epi64(index),
                                          _mm512_set1_epi64(static_cast<long long>(key))),
                         _mm512_set1_epi64(static_cast<long long>(k_mix64_first)));
  bits = _mm512_xor_si512(bits, _mm512_srli_epi64(bits, 29));
  low_x = _mm512_cvtepi64_epi32(_mm512_srli_epi64(bits, 32));
  low_y = _mm512_cvtepi64_epi32(bits);
}

[[MCRT_AVX512]] inline void make_block_avx512(const PaddedSetKeys& keys, std::uint32_t first,
                                              std::uint32_t count, unsigned h,
                                              std::array<Vec2, k_sobol_block>& points) {
  static_assert(k_sobol_block == 16, "one AVX-512 register of lanes");
  ShuffleRounds16 rounds;
  for (unsigned r = 0; r < 3; ++r) {
    rounds.a[r] = _mm512_set1_epi32(static_cast<int>(keys.round_a[r]));
    rounds.b[r] = _mm512_set1_epi32(static_cast<int>(keys.round_b[r]));
  }
  rounds.mask = _mm512_set1_epi32(static_cast<int>((std::uint32_t{1} << h) - 1));
  rounds.h = _mm_cvtsi32_si128(static_cast<int>(h));
  rounds.rest = _mm_cvtsi32_si128(static_cast<int>(32 - h));

  const __m512i index =
      _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(first)),
                       _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  __m512i p = shuffle_pass16(index, rounds);
  // Cycle walking, for the lanes of samples below count whose pass left them at count or above
  // (a lane past count could walk a cycle that never comes below it).
  const __m512i count_lanes = _mm512_set1_epi32(static_cast<int>(count));
  __mmask16 walking =
      _mm512_mask_cmpge_epu32_mask(_mm512_cmplt_epu32_mask(index, count_lanes), p, count_lanes);
  if (count <= 1) {
    p = _mm512_setzero_si512();
    walking = 0;
  }
  while (walking != 0) {
    p = _mm512_mask_mov_epi32(p, walking, shuffle_pass16(p, rounds));
    walking = _mm512_mask_cmpge_epu32_mask(walking, p, count_lanes);
  }

  __m512i dimension1 = p;
  dimension1 = xor_shifted16(dimension1, 1, 0x55555555u);
  dimension1 = xor_shifted16(dimension1, 2, 0x33333333u);
  dimension1 = xor_shifted16(dimension1, 4, 0x0f0f0f0fu);
  dimension1 = xor_shifted16(dimension1, 8, 0x00ff00ffu);
  dimension1 = xor_shifted16(dimension1, 16, 0x0000ffffu);
  const __m512i x_bits = reverse_bits16(laine_karras16(p, keys.seed_x));
  const __m512i y_bits = reverse_bits16(laine_karras16(dimension1, keys.seed_y));

  __m256i low_x, low_y;
  fill_bits8(_mm512_castsi512_si256(index), keys.key, low_x, low_y);
  store_points8(_mm512_castsi512_si256(x_bits), _mm512_castsi512_si256(y_bits), low_x, low_y,
                points.data());
  fill_bits8(_mm512_extracti64x4_epi64(index, 1), keys.key, low_x, low_y);
  store_points8(_mm512_extracti64x4_epi64(x_bits, 1), _mm512_extracti64x4_epi64(y_bits, 1), low_x,
                low_y, points.data() + 8);
}
#undef MCRT_AVX512
#endif

}  // namespace

void padded_sobol_block_portable(const PaddedSetKeys& keys, std::uint32_t first,
                                 std::uint32_t count, unsigned h,
                                 std::array<Vec2, k_sobol_block>& points) {
  make_block(keys, first, count, h, points);
}

#if defined(__x86_64__)
[[gnu::target("avx2")]] void padded_sobol_block_avx2(const PaddedSetKeys& keys, std::uint32_t first,
                                                     std::uint32_t count, unsigned h,
                                                     std::array<Vec2, k_sobol_block>& points) {
  make_block(keys, first, count, h, points);
}

[[gnu::target("avx512f,avx512bw,avx512vl,avx512dq")]] void padded_sobol_block_avx512(
    const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count, unsigned h,
    std::array<Vec2, k_sobol_block>& points) {
  make_block_avx512(keys, first, count, h, points);
}
#else
void padded_sobol_block_avx2(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                             unsigned h, std::array<Vec2, k_sobol_block>& points) {
  padded_sobol_block_portable(keys, first, count, h, points);
}

void padded_sobol_block_avx512(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                               unsigned h, std::array<Vec2, k_sobol_block>& points) {
  padded_sobol_block_portable(keys, first, count, h, points);
}
#endif

void padded_sobol_block(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                        unsigned h, std::array<Vec2, k_sobol_block>& points) {
  static const bool avx512 = cpu_has_avx512();
  static const bool avx2 = cpu_has_avx2();
  if (avx512)
    padded_sobol_block_avx512(keys, first, count, h, points);
  else if (avx2)
    padded_sobol_block_avx2(keys, first, count, h, points);
  else
    padded_sobol_block_portable(keys, first, count, h, points);
}

}  // namespace mcrt

#if defined(__x86_64__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
