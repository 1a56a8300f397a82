#pragma once
/// Owen's nested uniform scrambling of a binary fraction, by hash.
///
/// Owen (1995) flips each digit of a point with a coin that depends only on the digits above
/// it, so points that share a prefix keep sharing it: a (t,m,s)-net stays a (t,m,s)-net, and
/// every scrambled point is uniform on [0,1). Laine and Karras ("Stratified sampling for
/// stochastic transparency", 2011) observed that, on the bit-reversed word, a hash built from
/// additions and x ^= x * even constant has exactly that structure: each output bit depends
/// on the input bits below it (in reversed order, the digits above). Burley ("Practical
/// hash-based Owen scrambling", JCGT 9(4), 2020) gave the multipliers used here, chosen so
/// that the coins look independent.

#include <cstdint>

namespace mcrt {

/// The 32 bits of x in reverse order.
constexpr std::uint32_t reverse_bits(std::uint32_t x) {
  x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
  x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
  x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
  x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
  return (x >> 16) | (x << 16);
}

/// The Laine-Karras hash on a reversed word: bit k of the result depends on bits 0..k only
/// (a carry moves up, x * even moves bits up), and each step is a bijection.
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}

/// x (a 32-bit binary fraction, x / 2^32 in [0,1)) Owen-scrambled with the coins of `seed`.
constexpr std::uint32_t owen_scramble(std::uint32_t x, std::uint32_t seed) {
  return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
}

}  // namespace mcrt
