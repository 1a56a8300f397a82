// A padded Sobol' set's plain points (sampling/padded_sobol.hpp): dimension 1 from Lucas'
// theorem is Boost's, and the exact conversion is the plain one. (That the sets are nets,
// paired at random and unbiased: path_sampler_test.cpp and render/sampled_render_test.cpp;
// the blocks: padded_sobol_block_test.cpp.)

#include <cstdint>

#include <gtest/gtest.h>

#include "core/math.hpp"
#include "sampling/padded_sobol.hpp"
#include "sampling/sobol_matrices.hpp"

using namespace mcrt;

namespace {

// Column b alone, every index below 2^16, and some wide indices: the superset sum is the xor of
// Boost's columns of dimension 1, bit-reversed.
TEST(PaddedSobolTest, DimensionOneFromLucasIsBoosts) {
  for (unsigned b = 0; b < 32; ++b)
    EXPECT_EQ(sobol_dimension1_reversed(1u << b), reverse_bits(sobol_columns(1)[b])) << b;
  for (std::uint32_t i = 0; i < (1u << 16); ++i)
    ASSERT_EQ(sobol_dimension1_reversed(i), reverse_bits(sobol_bits(i, 1))) << i;
  for (std::uint32_t i : {0x12345678u, 0x80000001u, 0xfffffffeu, 0xffffffffu})
    EXPECT_EQ(sobol_dimension1_reversed(i), reverse_bits(sobol_bits(i, 1))) << i;
}

TEST(PaddedSobolTest, ExactDoubleIsTheConversion) {
  for (std::uint32_t x : {0u, 1u, 0x7fffffffu, 0x80000000u, 0x80000001u, 0xdeadbeefu, ~0u})
    EXPECT_EQ(exact_double(x), static_cast<double>(x)) << x;
}

}  // namespace
