#pragma once
/// The radical inverse: an index's digits mirrored about the radix point.
///
/// With i = sum_k d_k b^k (d_0 the least significant digit), phi_b(i) = sum_k d_k b^-(k+1).
/// phi_2(0), phi_2(1), ... is van der Corput's sequence (0, 1/2, 1/4, 3/4, 1/8, ...); dimension
/// j of a Halton point is phi_{p_j}(i), p_j the j-th prime. Its first b^m values are exactly the
/// b^m numbers k b^-m, one in each interval [k b^-m, (k+1) b^-m): the sequence is stratified
/// at every scale, and phi_b(b i + d) = (d + phi_b(i)) / b.

#include <cstdint>

namespace mcrt {

/// phi_b(i) for base b >= 2, to within a rounding.
inline double radical_inverse(std::uint32_t i, std::uint32_t base) {
  // ASSIGNMENT a7.3 BEGIN stub: (void)i; (void)base; NOT_IMPLEMENTED(radical_inverse);
  // The mirrored digits as a whole number over b^K (K the digits of i; both exact below
  // 2^53, as b^K <= b i < 2^40 here), divided once: correctly rounded.
  std::uint64_t mirrored = 0, scale = 1;
  for (std::uint32_t rest = i; rest != 0; rest /= base) {
    mirrored = mirrored * base + rest % base;
    scale *= base;
  }
  return static_cast<double>(mirrored) / static_cast<double>(scale);
  // ASSIGNMENT a7.3 END
}

}  // namespace mcrt
