#pragma once
/// The engine behind the disk estimator: the count M of estimate_disk_area's loop
/// (integration/disk_area.hpp), 16 points at a time.
///
/// The loop draws point i from lane i mod 16 of DiskPoints. Here every lane advances a whole
/// round (16 points) at once, four lanes per AVX2 register when the processor has AVX2, and
/// the inside test i^2 + j^2 <= 2^62 is the same exact integer test. So from the same `rng`
/// the count is the same, and the generator is left in the same state (tests/integration/disk_area_test).

#include <cstdint>

#include "core/rng.hpp"

namespace mcrt {

/// M: how many of n points of DiskPoints(rng) land in the unit disk (x^2 + y^2 <= 1); AVX2
/// when the processor has it.
std::uint64_t count_in_disk(std::uint64_t n, Rng& rng);
/// The same count without AVX2 (the reference the fast path must equal).
std::uint64_t count_in_disk_portable(std::uint64_t n, Rng& rng);
/// Whether count_in_disk runs its AVX2 path on this processor.
bool disk_count_uses_avx2();

/// 4 M / N with M from count_in_disk: estimate_disk_area's value from the same `rng`, fast.
double estimate_disk_area_fast(std::uint64_t n, Rng& rng);

/// Points per chunk of count_in_disk_parallel: ~4 ms of work, enough to hide the hand-over.
inline constexpr std::uint64_t k_disk_chunk = std::uint64_t{1} << 22;

/// M for n points on `threads` threads. The points are split into chunks of k_disk_chunk;
/// chunk j draws from Rng(seed, stream_index(stream, j)), so M does not depend on `threads`.
std::uint64_t count_in_disk_parallel(std::uint64_t n, std::uint64_t seed, std::uint64_t stream,
                                     int threads);

}  // namespace mcrt
