#pragma once
/// Random numbers: a PCG32 generator seeded by (seed, stream).
///
/// A stream is a pixel sample, a tile or a trial, never a thread, so results do not depend on
/// how work is scheduled. There is no global generator.

#include <cstdint>
#include <initializer_list>
#include <stdexcept>

#include <pcg_random.hpp>

#include "core/math.hpp"

namespace mcrt {

/// mix64's two multipliers (SplitMix64's), and the odd constant (2^64 / golden ratio) added to
/// a stream before Rng mixes it: named once for the four-lane seeding, which must agree.
inline constexpr std::uint64_t k_mix64_first = 0xbf58476d1ce4e5b9ULL;
inline constexpr std::uint64_t k_mix64_second = 0x94d049bb133111ebULL;
inline constexpr std::uint64_t k_stream_offset = 0x9e3779b97f4a7c15ULL;

/// SplitMix64's finaliser: a bijection of 64-bit words under which neighbouring inputs land
/// far apart.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * k_mix64_first;
  z = (z ^ (z >> 27)) * k_mix64_second;
  return z ^ (z >> 31);
}

class Rng {
 public:
  /// Generators with different (seed, stream) are independent sequences. PCG32 seeded with
  /// neighbouring raw values starts from neighbouring states, and its sequences stay
  /// correlated (seeds s and s + 1 agree in their fourth draws); so the starting state is
  /// scrambled by mix64. The stream still selects PCG's increment, so distinct streams are
  /// distinct sequences.
  Rng(std::uint64_t seed, std::uint64_t stream) : engine_(starting_state(seed, stream), stream) {}

  /// The seed PCG32 is given for (seed, stream): the scrambled one.
  static constexpr std::uint64_t starting_state(std::uint64_t seed, std::uint64_t stream) {
    return mix64(seed ^ mix64(stream + k_stream_offset));
  }

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

/// Stream index for (a, b) pairs such as (pixel, sample): a 2^32 + b, distinct for distinct
/// pairs while a < 2^32 and b < 2^32. The pixel loop's key.
constexpr std::uint64_t stream_index(std::uint64_t a, std::uint64_t b) { return (a << 32) ^ b; }

/// One part of a stream key: a value and how many values that part can take.
struct KeyPart {
  std::uint64_t value;
  std::uint64_t count;  ///< value < count
};

/// The stream of what an estimate serves, keyed by its parts, most significant first:
/// stream_key({{study, 4}, {size_index, 1 << 24}, {trial, 1ull << 32}}) is the mixed-radix
/// number ((study 2^24) + size_index) 2^32 + trial. Distinct keys give distinct streams as
/// long as every value is below its count and the product of the counts after the first
/// fits in 64 bits; both are checked, and a key that breaks them throws std::out_of_range.
/// stream_index(a, b) is stream_key({{a, 2^32}, {b, 2^32}}).
constexpr std::uint64_t stream_key(std::initializer_list<KeyPart> parts) {
  std::uint64_t key = 0;
  const std::uint64_t room = ~std::uint64_t{0};  // the largest key
  bool first = true;
  for (const KeyPart& part : parts) {
    if (part.value >= part.count) throw std::out_of_range("stream_key: a part is out of its range");
    if (!first) {
      if (key > room / part.count)
        throw std::out_of_range("stream_key: the key needs more than 64 bits");
      key *= part.count;
    }
    if (part.value > ~std::uint64_t{0} - key)
      throw std::out_of_range("stream_key: the key needs more than 64 bits");
    key += part.value;
    first = false;
  }
  return key;
}

}  // namespace mcrt
