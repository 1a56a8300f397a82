#pragma once
/// A random permutation of {0, ..., n-1} evaluated one element at a time, without storing it:
/// permutation_element(i, n, key) is where i goes. Latin hypercube points, padded jitter and
/// the digits of scrambled Halton points use it.
///
/// How: a keyed bijection of the w-bit words, 2^w >= n (each step below is invertible mod
/// 2^w), applied again while the result is >= n ("cycle walking"). Starting inside [0, n),
/// the walk stays on i's cycle and returns to [0, n) within that cycle, so the map restricted
/// to [0, n) is itself a bijection. Since 2^w < 2n, under two steps are expected. A small
/// family of hashes is not every permutation with equal chance (on 2 bits it is far from
/// it), so a random rotation, + c mod n with c uniform, follows: then each element goes to
/// each place with probability exactly 1/n over the keys, which is what makes the points of
/// Latin hypercube, jittered and Halton sets uniform.

#include <cstdint>

#include "sampling/point_random.hpp"

namespace mcrt {

namespace detail {

/// One keyed bijection of the w-bit words (mask = 2^w - 1): xor and add a key, multiply by
/// odd numbers, and xor-shift right, each invertible modulo 2^w.
constexpr std::uint64_t permute_word(std::uint64_t x, std::uint64_t mask, std::uint64_t k0,
                                     std::uint64_t k1, unsigned half) {
  x = ((x ^ k0) * 0xe817fb2d2d4ab1b3ULL) & mask;  // odd multiplier
  x ^= x >> half;
  x = ((x + k1) * ((k0 >> 1) | 1)) & mask;  // an odd multiplier of the key's
  x ^= x >> half;
  x = (x * 0x9e3779b97f4a7c15ULL) & mask;
  x ^= x >> half;
  return x;
}

}  // namespace detail

/// Where element i (< n) goes under the random permutation of {0, ..., n-1} named by key.
constexpr std::uint32_t permutation_element(std::uint32_t i, std::uint32_t n, std::uint64_t key) {
  if (n <= 1) return 0;
  unsigned w = 1;
  while ((std::uint64_t{1} << w) < n) ++w;
  const std::uint64_t mask = (std::uint64_t{1} << w) - 1;
  const unsigned half = w / 2 > 0 ? (w + 1) / 2 : 1;
  const std::uint64_t k0 = mix64(key + k_stream_offset);
  const std::uint64_t k1 = mix64(k0 ^ n);
  std::uint64_t x = i;
  do {
    x = detail::permute_word(x, mask, k0, k1, half);
  } while (x >= n);
  const std::uint64_t rotation = mix64(k1 + k_stream_offset) % n;  // bias below n / 2^64
  return static_cast<std::uint32_t>((x + rotation) % n);
}

}  // namespace mcrt
