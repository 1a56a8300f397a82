#pragma once
/// The point (cos 2 pi u, sin 2 pi u) of the unit circle, for the samplers' phi = 2 pi u.
///
/// Every direction sampler turns a uniform u into an angle phi = 2 pi u and needs its cosine
/// and sine. The maths library's sincos works for any angle, and pays for it: it was a fifth of
/// the path tracer's time. Here the angle is known to be a fraction of a turn, so the range
/// reduction is exact and two short polynomials do the rest:
///
///   4u = q + r with q the nearest whole number and |r| <= 1/2, so 2 pi u = q pi/2 + x with
///   x = r pi/2 in [-pi/4, pi/4]; cos x and sin x are their Taylor series to x^16 and x^15
///   (the first term left out is below (pi/4)^17 / 17! < 5e-17), and the quarter turns q only
///   swap and negate them.
///
/// Both values are within 3e-16 of the exact ones for u in [0, 1] (tests/core/cos_sin_test.cpp
/// checks it against long double): as close as std::cos(2 pi u), whose argument is already
/// rounded by up to 4.4e-16.

#include "core/math.hpp"

namespace mcrt {

/// (cos 2 pi u, sin 2 pi u) for u in [0, 1]. Branch-free: the quarter turn picks signs and
/// order from small tables, since u is random and a branch on it would mispredict.
inline Vec2 cos_sin_two_pi(double u) {
  const double quarters = 4.0 * u;                 // exact: a power of 2
  const int q = static_cast<int>(quarters + 0.5);  // nearest whole number, u >= 0
  const double x = (quarters - q) * (0.5 * k_pi);  // quarters - q is exact
  const double x2 = x * x;
  // Taylor series in x^2, by Horner's rule; the coefficients are 1/n! rounded once.
  const double sin_x =
      x + x * x2 *
              (-1.0 / 6 +
               x2 * (1.0 / 120 +
                     x2 * (-1.0 / 5040 +
                           x2 * (1.0 / 362880 +
                                 x2 * (-1.0 / 39916800 +
                                       x2 * (1.0 / 6227020800 + x2 * (-1.0 / 1307674368000.0)))))));
  const double cos_x =
      1.0 +
      x2 * (-1.0 / 2 +
            x2 * (1.0 / 24 +
                  x2 * (-1.0 / 720 +
                        x2 * (1.0 / 40320 + x2 * (-1.0 / 3628800 +
                                                  x2 * (1.0 / 479001600 +
                                                        x2 * (-1.0 / 87178291200.0 +
                                                              x2 * (1.0 / 20922789888000.0))))))));
  // cos(q pi/2 + x), sin(q pi/2 + x) for q mod 4 = 0, 1, 2, 3:
  // (cos x, sin x), (-sin x, cos x), (-cos x, -sin x), (sin x, -cos x).
  static constexpr double k_cos_sign[4] = {1.0, -1.0, -1.0, 1.0};
  static constexpr double k_sin_sign[4] = {1.0, 1.0, -1.0, -1.0};
  const double values[2] = {cos_x, sin_x};
  const int k = q & 3, swapped = q & 1;
  return {k_cos_sign[k] * values[swapped], k_sin_sign[k] * values[swapped ^ 1]};
}

}  // namespace mcrt
