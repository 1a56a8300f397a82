#pragma once
/// Four PCG32 generators per AVX2 register (x86-64 only): the step and the output of
/// core/pcg32_lanes.hpp, one instruction per operation for the four lanes, each lane's state
/// in a 64-bit lane.
///
/// AVX2 has no 64-bit multiply, so
///   s a mod 2^64 = lo(s) lo(a) + ((hi(s) lo(a) + lo(s) hi(a)) << 32),
/// from 32x32->64-bit products.

#if defined(__x86_64__)

#include <immintrin.h>

#include <cstdint>

namespace mcrt::avx2 {

/// A 64-bit multiplier a, split into its two 32-bit halves in every lane.
struct Pcg32Multiplier {
  __m256i low, high;
};

[[gnu::target("avx2")]] inline Pcg32Multiplier pcg32_multiplier(std::uint64_t a) {
  return {_mm256_set1_epi64x(static_cast<std::int64_t>(a & 0xffffffffu)),
          _mm256_set1_epi64x(static_cast<std::int64_t>(a >> 32))};
}

/// s a + c (mod 2^64), given the high half of s already shifted down (s_high = s >> 32), so
/// that two steps from the same s can share it.
[[gnu::target("avx2")]] inline __m256i pcg32_lcg(__m256i s, __m256i s_high, Pcg32Multiplier a,
                                                 __m256i c) {
  const __m256i cross =
      _mm256_add_epi64(_mm256_mul_epu32(s_high, a.low), _mm256_mul_epu32(s, a.high));
  return _mm256_add_epi64(_mm256_add_epi64(_mm256_mul_epu32(s, a.low),
                                           _mm256_slli_epi64(cross, 32)),
                          c);
}

/// PCG32's output in the low 32 bits of each 64-bit lane (the high 32 bits are not zero): the
/// xorshifted word is copied into both halves, so a 64-bit right shift by the rotation is a
/// 32-bit rotation of the low half.
[[gnu::target("avx2")]] inline __m256i pcg32_output(__m256i s) {
  const __m256i xorshifted = _mm256_srli_epi64(_mm256_xor_si256(_mm256_srli_epi64(s, 18), s), 27);
  const __m256i doubled = _mm256_shuffle_epi32(xorshifted, 0xA0);  // dwords (0,0,2,2,...)
  return _mm256_srlv_epi64(doubled, _mm256_srli_epi64(s, 59));
}

/// Rng::uniform() of each lane's output: its low 32 bits times 2^-32, exactly. The bits are
/// placed in the mantissa of 2^52 (whose last bit is worth 1), and 2^52 is taken away.
[[gnu::target("avx2")]] inline __m256d pcg32_uniform(__m256i output) {
  const __m256i two_52 = _mm256_set1_epi64x(0x4330000000000000);
  const __m256i bits = _mm256_and_si256(output, _mm256_set1_epi64x(0xffffffff));
  const __m256d value =
      _mm256_sub_pd(_mm256_castsi256_pd(_mm256_or_si256(bits, two_52)), _mm256_set1_pd(0x1p52));
  return _mm256_mul_pd(value, _mm256_set1_pd(0x1p-32));
}

}  // namespace mcrt::avx2

#endif
