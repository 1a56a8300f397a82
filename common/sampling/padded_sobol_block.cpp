#include "sampling/padded_sobol_block.hpp"

#include <algorithm>

#include "core/cpu_features.hpp"

namespace mcrt {

namespace {

// The plain steps, lane by lane in loops the compiler turns into vector code: one shuffle
// pass for every lane, the rare extra passes (cycle walking) one lane at a time, then the
// scrambles and the conversion. Inlined into each target's copy below.
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
#else
void padded_sobol_block_avx2(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                             unsigned h, std::array<Vec2, k_sobol_block>& points) {
  padded_sobol_block_portable(keys, first, count, h, points);
}
#endif

void padded_sobol_block(const PaddedSetKeys& keys, std::uint32_t first, std::uint32_t count,
                        unsigned h, std::array<Vec2, k_sobol_block>& points) {
  static const bool avx2 = cpu_has_avx2();
  if (avx2)
    padded_sobol_block_avx2(keys, first, count, h, points);
  else
    padded_sobol_block_portable(keys, first, count, h, points);
}

}  // namespace mcrt
