#pragma once
/// The generator matrices of Sobol' points, taken from Boost.Random's Sobol' engine (its
/// direction numbers are Joe and Kuo's, through ACM TOMS 659).
///
/// Point i of the sequence, dimension j, is the xor of the columns V_j[b] for the bits b set
/// in i: x_ij = (sum_b i_b V_j[b]) / 2^32 over GF(2). Its first 2^m points are a (t,m,s)-net:
/// in dimensions 0 and 1, t = 0, so each of the 2^m elementary boxes of area 2^-m
/// ([a 2^-k, (a+1) 2^-k) x [b 2^-(m-k), (b+1) 2^-(m-k))) holds exactly one point.

#include <array>
#include <cstdint>

namespace mcrt {

/// The most dimensions a Sobol' point set here has (the dimension study goes to 16; a path
/// pads its bounces instead of using more).
inline constexpr unsigned k_sobol_max_dimensions = 64;

/// The 32 columns of dimension j's generator matrix, for j < k_sobol_max_dimensions.
const std::array<std::uint32_t, 32>& sobol_columns(unsigned dimension);

/// Dimension j of the unscrambled Sobol' point i, as a 32-bit binary fraction.
inline std::uint32_t sobol_bits(std::uint32_t index, unsigned dimension) {
  const auto& columns = sobol_columns(dimension);
  std::uint32_t bits = 0;
  for (unsigned b = 0; index != 0; ++b, index >>= 1)
    if (index & 1u) bits ^= columns[b];
  return bits;
}

}  // namespace mcrt
