#pragma once
/// One sample's point in a padded Owen-scrambled Sobol' set, the plain version.
///
/// A pixel's spp samples are the points of 2D sets, one set per use (path_sampler.hpp). In a
/// Sobol' set, sample i is Sobol' point pi(i) (dimensions 0 and 1), pi a random permutation
/// of the samples, and each coordinate Owen-scrambled by a seed of the set. At spp = 2^m the
/// set is a (0,m,2)-net, and each point alone is uniform on [0,1)^2. padded_sobol_block.hpp
/// makes sixteen samples' points at once, the same bits.

#include <cstdint>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "sampling/owen_scramble.hpp"

namespace mcrt {

/// What a 2D set of a pixel needs whatever the sample, made once per pixel: its key (jittered:
/// its permutation of the cells; both: the low bits of each sample) and, for Sobol' sets, the
/// two Owen scrambles and the three rounds of the sample shuffle.
/// No initialisers: a pixel's cache of them is left unwritten until a sample reaches a set.
struct PaddedSetKeys {
  std::uint64_t key;
  std::uint32_t seed_x, seed_y;          ///< sobol: the coordinates' Owen scrambles
  std::uint32_t round_a[3], round_b[3];  ///< sobol: the shuffle's round functions
};

/// The key of 2D set `set` (0: the pixel position, 1 + b: bounce b) of pixel_key's pixel.
inline std::uint64_t padded_set_key(std::uint64_t pixel_key, unsigned set) {
  return mix64(pixel_key + (set + std::uint64_t{1}) * k_stream_offset);
}

/// The Sobol' set's scrambles and rounds from its key: each a mix64 (SplitMix64's
/// finaliser) of the key stepped by the golden-ratio constant.
inline void make_sobol_set_keys(PaddedSetKeys& keys) {
  const std::uint64_t seeds = mix64(keys.key);
  keys.seed_x = static_cast<std::uint32_t>(seeds);
  keys.seed_y = static_cast<std::uint32_t>(seeds >> 32);
  for (unsigned r = 0; r < 3; ++r) {
    const std::uint64_t round = mix64(keys.key + (r + std::uint64_t{2}) * k_stream_offset);
    keys.round_a[r] = static_cast<std::uint32_t>(round);
    keys.round_b[r] = static_cast<std::uint32_t>(round >> 32);
  }
}

/// The half width h of the sample shuffle's words for n samples: the least h with 2^(2h) >= n.
inline unsigned shuffle_half_bits(std::uint32_t n) {
  unsigned h = 1;
  while ((std::uint64_t{1} << (2 * h)) < n) ++h;
  return h;
}

/// One pass of the sample shuffle: a three-round Feistel network on the 2h bits of x, round
/// r's function F_r(v) = ((a_r v + b_r) mod 2^32) >> (32 - h). A bijection of [0, 2^(2h)).
constexpr std::uint32_t shuffle_pass(std::uint32_t x, unsigned h, const PaddedSetKeys& keys) {
  const std::uint32_t mask = (std::uint32_t{1} << h) - 1;
  std::uint32_t left = x >> h, right = x & mask;
  for (unsigned r = 0; r < 3; ++r) {
    const std::uint32_t f = (keys.round_a[r] * right + keys.round_b[r]) >> (32 - h);
    const std::uint32_t next = left ^ f;
    left = right;
    right = next;
  }
  return left << h | right;
}

/// Where sample i goes under the random permutation of {0, ..., n-1} of a set (n >= 2, h =
/// shuffle_half_bits(n)): shuffle passes until the result is below n (cycle walking, as in
/// permutation.hpp; from i < n the walk ends, at i itself at the latest).
/// With a_r, b_r uniform, F_r is Dietzfelbinger's multiply-add-shift hash, pairwise independent
/// for inputs of at most 32 - h bits (v has h <= 16). Three rounds of random functions make a
/// permutation that queries of its forward direction, which is all a pairing of samples is,
/// cannot tell from a random one (Luby and Rackoff); the pairing test checks ours, at a
/// multiply per round. The lighter permutation_element keeps enough of the index's low bits
/// that two sets' first Sobol' digits, which are those bits, stay correlated; an
/// Owen-scrambled index keeps the pairs {2k, 2k+1} together, with the same effect.
inline std::uint32_t shuffled_sample(std::uint32_t i, std::uint32_t n, unsigned h,
                                     const PaddedSetKeys& keys) {
  std::uint32_t x = i;
  do x = shuffle_pass(x, h, keys);
  while (x >= n);
  return x;
}

/// Dimension 1 of Sobol' point p, its bits reversed (bit k is the digit of weight 2^-(k+1)).
/// Dimension 1's generator matrix is Pascal's triangle mod 2: column b has digit k set when
/// C(b, k) is odd, that is (Lucas) when k's bits are a subset of b's. So digit k is the xor of
/// the index bits b that contain k: a superset sum over the five bits of a bit position, made
/// one position bit j at a time, each step adding bit k + 2^j into every k without bit j.
/// tests/sampling/padded_sobol_test.cpp checks it against Boost's columns.
constexpr std::uint32_t sobol_dimension1_reversed(std::uint32_t p) {
  p ^= (p >> 1) & 0x55555555u;   // k without bit 0 takes k + 1
  p ^= (p >> 2) & 0x33333333u;   // without bit 1: k + 2
  p ^= (p >> 4) & 0x0f0f0f0fu;   // without bit 2: k + 4
  p ^= (p >> 8) & 0x00ff00ffu;   // without bit 3: k + 8
  p ^= (p >> 16) & 0x0000ffffu;  // without bit 4: k + 16
  return p;
}

/// x as a double, exactly (a conversion the compiler makes in vector registers, unlike the
/// unsigned one: x - 2^31 is a signed 32-bit integer).
constexpr double exact_double(std::uint32_t x) {
  return static_cast<double>(static_cast<std::int32_t>(x ^ 0x80000000u)) + 0x1p31;
}

/// The point (x_bits, y_bits) / 2^32 of sample `index` of the set, with the bits below the 32
/// scrambled ones filled in, so that it is uniform in double precision: a 2^-32 refinement no
/// estimate can resolve, so one multiply-xorshift of (key, index) serves (uniform over the
/// keys; each half of the word a different refinement).
constexpr Vec2 padded_point_from_bits(std::uint32_t x_bits, std::uint32_t y_bits, std::uint64_t key,
                                      std::uint32_t index) {
  std::uint64_t low_bits = (key ^ index) * k_mix64_first;
  low_bits ^= low_bits >> 29;
  const double low_x = exact_double(static_cast<std::uint32_t>(low_bits >> 32)) * 0x1p-32;
  const double low_y = exact_double(static_cast<std::uint32_t>(low_bits)) * 0x1p-32;
  return {(exact_double(x_bits) + low_x) * 0x1p-32, (exact_double(y_bits) + low_y) * 0x1p-32};
}

/// Sample `index`'s point in the Sobol' set of `keys`, of `count` samples (h =
/// shuffle_half_bits(count)): dimensions 0 and 1 of Sobol' point p = pi(index), each
/// Owen-scrambled by the set's seeds. Owen scrambling works on reversed bits
/// (owen_scramble.hpp): dimension 0, the radical inverse, is the index reversed, so its
/// reversed bits are p itself.
inline Vec2 padded_sobol_point(const PaddedSetKeys& keys, std::uint32_t index, std::uint32_t count,
                               unsigned h) {
  const std::uint32_t p = count <= 1 ? 0 : shuffled_sample(index, count, h, keys);
  const std::uint32_t x_bits = reverse_bits(laine_karras_permutation(p, keys.seed_x));
  const std::uint32_t y_bits =
      reverse_bits(laine_karras_permutation(sobol_dimension1_reversed(p), keys.seed_y));
  return padded_point_from_bits(x_bits, y_bits, keys.key, index);
}

}  // namespace mcrt
