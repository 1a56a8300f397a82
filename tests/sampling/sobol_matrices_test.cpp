// The Sobol' generator matrices read from Boost (sampling/sobol_matrices.hpp) against the
// sequence's known first columns and points. (The net property: point_sets_test.cpp.)

#include <cstdint>
#include <stdexcept>

#include <gtest/gtest.h>

#include "sampling/sobol_matrices.hpp"

using namespace mcrt;

namespace {

TEST(SobolTest, DimensionZeroIsVanDerCorputAndOneIsPascal) {
  for (unsigned b = 0; b < 32; ++b) EXPECT_EQ(sobol_columns(0)[b], 1u << (31 - b));
  // Dimension 1 (direction numbers 1/2, 3/4, 5/8): in natural order 0, 1/2, 3/4, 1/4, 5/8,
  // 1/8, 3/8, 7/8.
  const double expected[] = {0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
  for (std::uint32_t i = 0; i < 8; ++i)
    EXPECT_EQ(sobol_bits(i, 1) * 0x1p-32, expected[i]) << "point " << i;
}

TEST(SobolTest, RefusesDimensionsBeyondTheTable) {
  EXPECT_THROW(sobol_columns(k_sobol_max_dimensions), std::out_of_range);
}

}  // namespace
