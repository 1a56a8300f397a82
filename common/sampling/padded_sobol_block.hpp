#pragma once
/// Eight samples' points of one padded Sobol' set at once: padded_sobol_point's bits, made in
/// vector registers (AVX2 when the processor has it). PaddedPixel makes a set's points a block
/// at a time, when the first sample of the block reaches the set; the estimator then reads
/// them. tests/sampling/padded_sobol_test.cpp compares every point with the plain version.

#include <array>
#include <cstdint>

#include "core/math.hpp"
#include "sampling/padded_sobol.hpp"

namespace mcrt {

inline constexpr unsigned k_sobol_block = 8;

/// points[i] = padded_sobol_point(keys, first + i, count, h) for each first + i < count
/// (the points past count are left unspecified): the AVX2 version when the processor has it.
void padded_sobol_block(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                        unsigned h, std::array<Vec2, k_sobol_block>& points);

/// The same, compiled for any x86-64 (or any processor) and for AVX2 (off x86, the portable
/// one again); the test compares both with the plain version.
void padded_sobol_block_portable(const PaddedSetKeys& keys, std::uint32_t first,
                                 std::uint32_t count, unsigned h,
                                 std::array<Vec2, k_sobol_block>& points);
void padded_sobol_block_avx2(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                             unsigned h, std::array<Vec2, k_sobol_block>& points);

}  // namespace mcrt
