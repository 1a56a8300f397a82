#pragma once
/// Sixteen samples' points of one padded Sobol' set at once: padded_sobol_point's bits, made in
/// vector registers (AVX-512 or AVX2, whichever the processor has). PaddedPixel makes a set's
/// points a block at a time, when the first sample of the block reaches the set; the estimator
/// then reads them. tests/sampling/padded_sobol_block_test.cpp compares every point with the
/// plain version.

#include <array>
#include <cstdint>

#include "core/math.hpp"
#include "sampling/padded_sobol.hpp"

namespace mcrt {

/// Sixteen lanes: one AVX-512 register of 32-bit words. A block of paths wastes the points of
/// the samples whose paths end before the set; at depth 10, one in sixteen samples reaches the
/// last set nearly as often as one in eight does, so the wider block wastes little more.
inline constexpr unsigned k_sobol_block = 16;

/// points[i] = padded_sobol_point(keys, first + i, count, h) for each first + i < count
/// (the points past count are left unspecified): the fastest version the processor runs.
void padded_sobol_block(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                        unsigned h, std::array<Vec2, k_sobol_block>& points);

/// The same, compiled for any processor, for AVX2 and for AVX-512 (F, BW, VL and DQ); off
/// x86-64 the last two are the portable one again. The test compares each with the plain
/// version where the processor runs it.
void padded_sobol_block_portable(const PaddedSetKeys& keys, std::uint32_t first,
                                 std::uint32_t count, unsigned h,
                                 std::array<Vec2, k_sobol_block>& points);
void padded_sobol_block_avx2(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                             unsigned h, std::array<Vec2, k_sobol_block>& points);
void padded_sobol_block_avx512(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                               unsigned h, std::array<Vec2, k_sobol_block>& points);

}  // namespace mcrt
