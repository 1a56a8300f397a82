// Owen scrambling by hash (sampling/owen_scramble.hpp): bits reversed exactly, the scramble
// a bijection that keeps shared prefixes shared. (That scrambled nets stay nets and their
// points are uniform: point_sets_test.cpp.)

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "sampling/owen_scramble.hpp"

using namespace mcrt;

namespace {

TEST(OwenScrambleTest, ReverseBitsReversesAndIsItsOwnInverse) {
  EXPECT_EQ(reverse_bits(1u), 0x80000000u);
  EXPECT_EQ(reverse_bits(0x0000000fu), 0xf0000000u);
  EXPECT_EQ(reverse_bits(0x12345678u), 0x1e6a2c48u);
  for (std::uint32_t x : {0u, 7u, 0xdeadbeefu, 0xffffffffu})
    EXPECT_EQ(reverse_bits(reverse_bits(x)), x);
}

TEST(OwenScrambleTest, IsABijectionOfTheTopBits) {
  // Scrambling permutes the 2^16 prefixes of 16 bits (it would map two points of a net to
  // one box otherwise).
  for (std::uint32_t seed : {0u, 12345u}) {
    std::vector<bool> seen(1u << 16, false);
    for (std::uint32_t x = 0; x < (1u << 16); ++x) seen[owen_scramble(x << 16, seed) >> 16] = true;
    for (const bool s : seen) ASSERT_TRUE(s);
  }
}

TEST(OwenScrambleTest, KeepsPrefixesTogether) {
  // Nested: two words that share their top k bits still share them after scrambling, and a
  // word's scrambled top k bits depend on its top k bits only.
  for (std::uint32_t seed : {0u, 1u, 0x9e3779b9u})
    for (std::uint32_t x = 0; x < 4096; ++x) {
      const std::uint32_t a = x << 20;
      const std::uint32_t b = a | 0x000fffffu;  // the same top 12 bits, the rest all ones
      ASSERT_EQ(owen_scramble(a, seed) >> 20, owen_scramble(b, seed) >> 20);
    }
}

}  // namespace
