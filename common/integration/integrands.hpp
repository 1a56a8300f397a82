#pragma once
/// Integrands with closed-form integrals, for studying quadrature and Monte Carlo.
///
/// Each one is a callable with its domain, its integral I (`reference`) and the integral of
/// its square J (`integral_of_square`), which gives Monte Carlo's variance
/// V[F_N] = (vol J - I^2) / N. Chapter 03 studies the first four; the last two are the
/// lecture's examples of integrals that do have a closed form.

#include <cmath>
#include <span>

#include "core/math.hpp"
#include "integration/ball.hpp"
#include "integration/domain.hpp"

namespace mcrt {

/// 1. Smooth, 1D: e^(-x^2) on [0, 1]. No elementary antiderivative, but
/// I = sqrt(pi)/2 erf(1) and J = integral of e^(-2 x^2) = sqrt(pi/8) erf(sqrt 2).
struct Gaussian1D {
  Segment domain{0.0, 1.0};
  double operator()(double x) const { return std::exp(-x * x); }
  double reference() const { return 0.5 * std::sqrt(k_pi) * std::erf(1.0); }
  double integral_of_square() const { return std::sqrt(k_pi / 8.0) * std::erf(std::sqrt(2.0)); }
};

/// 2. Discontinuous, 1D: ceil(sin x^2) on [0, 3]. It is 1 where sin x^2 > 0, that is on
/// (0, sqrt pi) and (sqrt(2 pi), 3] (3^2 < 3 pi), and 0 elsewhere: two jumps inside the
/// interval and one at x = 0. I = J = sqrt(pi) + 3 - sqrt(2 pi).
struct CeilSinSquare1D {
  Segment domain{0.0, 3.0};
  double operator()(double x) const { return std::ceil(std::sin(x * x)); }
  double reference() const { return std::sqrt(k_pi) + 3.0 - std::sqrt(2.0 * k_pi); }
  double integral_of_square() const { return reference(); }
};

/// 3. Smooth, k dimensions: prod_i e^(-x_i^2) on [0, 1]^k. It separates, so
/// I = (sqrt(pi)/2 erf(1))^k and J = (sqrt(pi/8) erf(sqrt 2))^k.
struct GaussianProduct {
  int dims = 1;
  Box domain() const { return Box::cube(dims, 0.0, 1.0); }
  double operator()(std::span<const double> x) const {
    double r2 = 0.0;
    for (double xi : x) r2 += xi * xi;
    return std::exp(-r2);  // prod_i e^(-x_i^2) = e^(-|x|^2): one exponential, same function
  }
  double reference() const { return std::pow(Gaussian1D{}.reference(), dims); }
  double integral_of_square() const { return std::pow(Gaussian1D{}.integral_of_square(), dims); }
};

/// 4. Discontinuous, k dimensions: the indicator of the unit ball in [-1, 1]^k (k = 2: the
/// lecture's disk). I = J = V_k, the ball's volume.
struct UnitBallIndicator {
  int dims = 2;
  Box domain() const { return Box::cube(dims, -1.0, 1.0); }
  double operator()(std::span<const double> x) const { return inside_unit_ball(x) ? 1.0 : 0.0; }
  double reference() const { return unit_ball_volume(dims); }
  double integral_of_square() const { return reference(); }
};

/// The lecture's closed form: integral of x^3 is x^4/4 (J: integral of x^6 is x^7/7).
struct Cubic {
  Segment domain{0.0, 2.0};
  double operator()(double x) const { return x * x * x; }
  static double antiderivative(double x) { return x * x * x * x / 4.0; }
  double reference() const { return antiderivative(domain.upper) - antiderivative(domain.lower); }
  double integral_of_square() const {
    return (std::pow(domain.upper, 7) - std::pow(domain.lower, 7)) / 7.0;
  }
};

/// The lecture's closed form: integral of x cos x is x sin x + cos x (integration by parts).
/// J: integral of x^2 cos^2 x is x^3/6 + x^2 sin(2x)/4 + x cos(2x)/4 - sin(2x)/8.
struct XCosX {
  Segment domain{0.0, 0.5 * k_pi};
  double operator()(double x) const { return x * std::cos(x); }
  static double antiderivative(double x) { return x * std::sin(x) + std::cos(x); }
  static double antiderivative_of_square(double x) {
    return x * x * x / 6.0 + x * x * std::sin(2.0 * x) / 4.0 + x * std::cos(2.0 * x) / 4.0 -
           std::sin(2.0 * x) / 8.0;
  }
  double reference() const { return antiderivative(domain.upper) - antiderivative(domain.lower); }
  double integral_of_square() const {
    return antiderivative_of_square(domain.upper) - antiderivative_of_square(domain.lower);
  }
};

}  // namespace mcrt
