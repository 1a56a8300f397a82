#pragma once
/// Random numbers: a PCG32 generator seeded by (seed, stream).
///
/// A stream is a pixel sample, a tile or a trial, never a thread, so results do not depend on
/// how work is scheduled. There is no global generator.

#include <cstdint>

#include <pcg_random.hpp>

#include "math.hpp"

namespace mcrt {

/// SplitMix64's finaliser: a bijection of 64-bit words under which neighbouring inputs land
/// far apart.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  /// Generators with different (seed, stream) are independent sequences. PCG32 seeded with
  /// neighbouring raw values starts from neighbouring states, and its sequences stay
  /// correlated (seeds s and s + 1 agree in their fourth draws); so the starting state is
  /// scrambled by mix64. The stream still selects PCG's increment, so distinct streams are
  /// distinct sequences.
  Rng(std::uint64_t seed, std::uint64_t stream)
      : engine_(mix64(seed ^ mix64(stream + 0x9e3779b97f4a7c15ULL)), stream) {}

  /// 32 uniformly random bits.
  std::uint32_t next_bits() { return engine_(); }

  /// Uniform in [0, 1): 32 random bits scaled by 2^-32, so 1 is never returned.
  double uniform() { return next_bits() * 0x1p-32; }

  /// Two independent uniforms in [0, 1)^2, the argument every 2D sampler takes.
  Vec2 uniform2() {
    const double u0 = uniform();
    return {u0, uniform()};
  }

  /// Uniform integer in [0, bound), without modulo bias.
  std::uint32_t uniform_below(std::uint32_t bound) { return engine_(bound); }

 private:
  pcg32 engine_;
};

/// Stream index for (a, b) pairs such as (pixel, sample): distinct for distinct pairs while
/// b < 2^32.
constexpr std::uint64_t stream_index(std::uint64_t a, std::uint64_t b) { return (a << 32) ^ b; }

}  // namespace mcrt
