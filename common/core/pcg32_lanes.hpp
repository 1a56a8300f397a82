#pragma once
/// Several PCG32 generators side by side, stored as arrays with one entry per lane, so that
/// one AVX2 instruction can advance four of them. Lane l gives exactly the numbers of
/// pcg32(seed_l, stream_l), the engine behind mcrt::Rng; the lanes only change how many
/// generators run at once, not the generator.
///
/// PCG32 (XSH-RR 64/32): state' = a state + c (mod 2^64), c odd; the output of a state s is
///   rotr32(uint32((s ^ (s >> 18)) >> 27), s >> 59),
/// and each call returns the output of the current state, then advances it.

#include <array>
#include <cstdint>

#include "core/rng.hpp"

namespace mcrt {

/// The multiplier a of PCG32's linear congruential step.
inline constexpr std::uint64_t k_pcg32_multiplier = 6364136223846793005ULL;

/// PCG32's output permutation of a 64-bit state.
constexpr std::uint32_t pcg32_output(std::uint64_t state) {
  const auto xorshifted = static_cast<std::uint32_t>(((state >> 18) ^ state) >> 27);
  const auto rotation = static_cast<std::uint32_t>(state >> 59);
  return (xorshifted >> rotation) | (xorshifted << ((32 - rotation) & 31));
}

template <int Lanes>
struct Pcg32Lanes {
  static constexpr int k_lanes = Lanes;
  std::array<std::uint64_t, Lanes> state{};
  std::array<std::uint64_t, Lanes> increment{};  ///< c = 2 stream + 1

  /// Lane l becomes pcg32(seed, stream): c = 2 stream + 1, state = (seed + c) a + c.
  void seed_lane(int l, std::uint64_t seed, std::uint64_t stream) {
    increment[l] = (stream << 1) | 1u;
    state[l] = (seed + increment[l]) * k_pcg32_multiplier + increment[l];
  }

  /// Every lane seeded with a 64-bit seed and a 63-bit stream drawn from `rng`.
  void seed_from(Rng& rng) {
    auto draw64 = [&rng] {
      const std::uint64_t high = rng.next_bits();
      return (high << 32) | rng.next_bits();
    };
    for (int l = 0; l < Lanes; ++l) {
      const std::uint64_t seed = draw64();
      seed_lane(l, seed, draw64());
    }
  }

  /// The next 32 bits of lane l.
  std::uint32_t next(int l) {
    const std::uint64_t old = state[l];
    state[l] = old * k_pcg32_multiplier + increment[l];
    return pcg32_output(old);
  }
};

}  // namespace mcrt
