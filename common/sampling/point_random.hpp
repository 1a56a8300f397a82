#pragma once
/// Random numbers for point sets, by address rather than by stream: the uniform for
/// (key, index, dimension) is a hash of the three, so the i-th point of a set can be made
/// without making the ones before it, in any order and on any thread.

#include <cstdint>

#include "core/rng.hpp"

namespace mcrt {

/// 64 well-mixed bits for (key, a, b): distinct addresses give unrelated words (mix64 is a
/// bijection, applied to the key and to each part in turn).
constexpr std::uint64_t hash_bits(std::uint64_t key, std::uint64_t a, std::uint64_t b) {
  return mix64(mix64(mix64(key + k_stream_offset) ^ a) + b);
}

/// Uniform in [0, 1) for (key, a, b): the top 53 bits scaled by 2^-53.
constexpr double hash_uniform(std::uint64_t key, std::uint64_t a, std::uint64_t b) {
  return static_cast<double>(hash_bits(key, a, b) >> 11) * 0x1p-53;
}

}  // namespace mcrt
