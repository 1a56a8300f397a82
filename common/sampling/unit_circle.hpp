#pragma once
/// The point at angle 2 pi u on the unit circle, (cos 2 pi u, sin 2 pi u), without a call to
/// the maths library: the angle sampled on every bounce of every path.

#include "core/math.hpp"

namespace mcrt {

namespace unit_circle_detail {

// Taylor series of sin and cos on [0, pi/4] by Horner's rule in x^2, the signs alternating
// through the subtractions: sin x = x (1/1! - x^2 (1/3! - x^2 (1/5! - ...))). The first terms
// left out, x^17/17! and x^18/18!, are below 5e-17 there: the sums are exact to rounding.
constexpr double inverse_factorial(int n) { return n <= 1 ? 1.0 : inverse_factorial(n - 1) / n; }

inline double sin_quarter(double x) {
  const double x2 = x * x;
  double sum = inverse_factorial(15);
  sum = inverse_factorial(13) - x2 * sum;
  sum = inverse_factorial(11) - x2 * sum;
  sum = inverse_factorial(9) - x2 * sum;
  sum = inverse_factorial(7) - x2 * sum;
  sum = inverse_factorial(5) - x2 * sum;
  sum = inverse_factorial(3) - x2 * sum;
  sum = 1.0 - x2 * sum;
  return x * sum;
}

inline double cos_quarter(double x) {
  const double x2 = x * x;
  double sum = inverse_factorial(16);
  sum = inverse_factorial(14) - x2 * sum;
  sum = inverse_factorial(12) - x2 * sum;
  sum = inverse_factorial(10) - x2 * sum;
  sum = inverse_factorial(8) - x2 * sum;
  sum = inverse_factorial(6) - x2 * sum;
  sum = inverse_factorial(4) - x2 * sum;
  sum = inverse_factorial(2) - x2 * sum;
  return 1.0 - x2 * sum;
}

}  // namespace unit_circle_detail

/// (cos 2 pi u, sin 2 pi u) for u in [0, 1), within 1e-15 of the exact values.
///
/// 2 pi u = (pi/2) (q + f): q quarter turns, then an angle a = (pi/2) f in the quarter, f in
/// [0, 1) (4u and 4u - q are exact). cos a and sin a come from series on [0, pi/4]: directly
/// for f <= 1/2, else as sin and cos of pi/2 - a = (pi/2)(1 - f) (1 - f is exact there). Then
/// q quarter turns, each (c, s) -> (-s, c). Why: no call into libm and no argument reduction
/// on every bounce; 1.03x to 1.17x the path tracer's rays per second (bench_path_tracer).
inline Vec2 unit_circle_point(double u) {
  using namespace unit_circle_detail;
  constexpr double k_half_pi = 0.5 * k_pi;
  const double quarters = 4.0 * u;
  const int q = static_cast<int>(quarters);
  const double f = quarters - q;
  const bool upper = f > 0.5;
  const double x = k_half_pi * (upper ? 1.0 - f : f);
  const double sin_x = sin_quarter(x), cos_x = cos_quarter(x);
  double c = upper ? sin_x : cos_x;
  double s = upper ? cos_x : sin_x;
  if (q & 1) {  // a quarter turn
    const double c0 = c;
    c = -s;
    s = c0;
  }
  if (q & 2) {  // a half turn
    c = -c;
    s = -s;
  }
  return {c, s};
}

}  // namespace mcrt
