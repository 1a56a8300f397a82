#pragma once
/// The unit ball in k dimensions: its exact volume and the membership test.

#include <cmath>
#include <span>

#include "core/math.hpp"

namespace mcrt {

/// V_k = pi^(k/2) / Gamma(k/2 + 1): V_0 = 1, V_1 = 2, V_2 = pi, V_3 = 4 pi / 3, ...
inline double unit_ball_volume(int k) {
  return std::pow(k_pi, 0.5 * k) / std::tgamma(0.5 * k + 1.0);
}

/// Whether |x| <= 1.
inline bool inside_unit_ball(std::span<const double> x) {
  double r2 = 0.0;
  for (double xi : x) r2 += xi * xi;
  return r2 <= 1.0;
}

}  // namespace mcrt
