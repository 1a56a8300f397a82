// The trapezoid rules: exact where theory says so, O(h^2) on smooth integrands with the
// constant Euler-Maclaurin predicts, O(h) where the integrand jumps.

#include "integration/quadrature.hpp"

#include <cmath>
#include <span>
#include <vector>

#include <gtest/gtest.h>

#include "integration/integrands.hpp"
#include "integration/log_grid.hpp"
#include "integration/statistics.hpp"

namespace {

using mcrt::Box;
using mcrt::Segment;

// Round-off bound for a rule that is exact in exact arithmetic: a compensated sum loses a few
// ulps, the weights and grid points a few more; 1e-13 relative leaves a factor of ~50 over that.
constexpr double k_roundoff = 1e-13;

TEST(Trapezoid1D, ExactForLinearFunctions) {
  const auto f = [](double x) { return 3.0 * x - 2.0; };
  const Segment segment{-1.0, 2.5};
  // integral of 3x - 2 = 3/2 (b^2 - a^2) - 2 (b - a)
  const double exact = 1.5 * (2.5 * 2.5 - 1.0) - 2.0 * 3.5;
  for (std::uint64_t n : {2, 3, 7, 1000})
    EXPECT_NEAR(mcrt::trapezoid(f, segment, n), exact, k_roundoff * 10.0) << n;
}

TEST(TrapezoidBox, ExactForMultilinearFunctions) {
  // f = prod_i (a_i + b_i x_i) + c x_0 x_2: linear in each coordinate when the others are
  // fixed, so the rule is exact along every axis and hence on the box.
  Box box;
  box.dims = 3;
  box.lower = {0.0, -1.0, 0.5};
  box.upper = {1.0, 2.0, 1.5};
  const double a[3] = {1.0, -0.5, 2.0}, b[3] = {2.0, 1.5, -1.0}, c = 3.0;
  const auto f = [&](std::span<const double> x) {
    return (a[0] + b[0] * x[0]) * (a[1] + b[1] * x[1]) * (a[2] + b[2] * x[2]) + c * x[0] * x[2];
  };
  // Closed form: integral of a product of one-variable factors is the product of integrals.
  double product = 1.0;
  for (int i = 0; i < 3; ++i) {
    const double l = box.lower[i], u = box.upper[i];
    product *= a[i] * (u - l) + b[i] * (u * u - l * l) / 2.0;
  }
  // c * (integral of x_0 over [0,1]) * (length of [-1,2]) * (integral of x_2 over [0.5,1.5])
  const double cross = c * 0.5 * 3.0 * ((1.5 * 1.5 - 0.5 * 0.5) / 2.0);
  const double exact = product + cross;
  for (std::uint64_t n : {2, 3, 6, 41})
    EXPECT_NEAR(mcrt::trapezoid(f, box, n), exact, k_roundoff * std::abs(exact) * 10.0) << n;
}

TEST(TrapezoidBox, NotExactForAQuadratic) {
  // The same rule on x_0^2 is off by (b - a) h^2 / 12 * f'' = h^2 / 6 on [0,1]: exactness
  // above is a property of multilinear functions, not of the test.
  const Box box = Box::cube(2, 0.0, 1.0);
  const auto f = [](std::span<const double> x) { return x[0] * x[0]; };
  const double h = 1.0 / 4.0;
  EXPECT_NEAR(mcrt::trapezoid(f, box, 5) - 1.0 / 3.0, h * h / 6.0, k_roundoff);
}

TEST(TrapezoidBox, OneDimensionalBoxMatchesSegmentRule) {
  const mcrt::Gaussian1D g;
  const auto on_box = [&](std::span<const double> x) { return g(x[0]); };
  for (std::uint64_t n : {2, 9, 100})
    EXPECT_NEAR(mcrt::trapezoid(on_box, Box::cube(1, 0.0, 1.0), n), mcrt::trapezoid(g, g.domain, n),
                k_roundoff);
}

TEST(TrapezoidGrid, SymmetricGridHitsZeroAndTheEndsExactly) {
  // Points of a grid on [-1, 1] with odd n land exactly on 0 and +-1: lattice effects on
  // the disk come from geometry, not from an ulp of round-off.
  for (std::uint64_t n : {3, 5, 101, 1001}) {
    EXPECT_EQ(mcrt::grid_point(-1.0, 1.0, 0, n), -1.0);
    EXPECT_EQ(mcrt::grid_point(-1.0, 1.0, (n - 1) / 2, n), 0.0);
    EXPECT_EQ(mcrt::grid_point(-1.0, 1.0, n - 1, n), 1.0);
  }
}

// Euler-Maclaurin: T_n - I = h^2/12 (f'(b) - f'(a)) - h^4/720 (f'''(b) - f'''(a)) + ...
// For e^(-x^2) on [0,1]: f'(1) - f'(0) = -2/e, f'''(1) - f'''(0) = 4/e, so
// E(h) / E(h/2) = 4 (1 + r h^2) / (1 + r h^2 / 4) with r = -(4/e/720) / (-2/e/12) = 1/30;
// at h = 1/8 that is 4.0016, closer to 4 for smaller h. Tolerance 0.01: six times that.
TEST(Trapezoid1D, ErrorFallsFourfoldWhenIntervalsDouble) {
  const mcrt::Gaussian1D g;
  for (std::uint64_t intervals = 8; intervals <= 2048; intervals *= 2) {
    const double coarse = mcrt::trapezoid(g, g.domain, intervals + 1) - g.reference();
    const double fine = mcrt::trapezoid(g, g.domain, 2 * intervals + 1) - g.reference();
    EXPECT_NEAR(coarse / fine, 4.0, 0.01) << intervals << " intervals";
  }
}

// In k = 3 the product rule gives T^3 with T = I + e per axis, so the error is
// 3 I^2 e + 3 I e^2 + e^3, and halving h changes it by 4 (1 + 3 e_fine / I + ...). At 8
// intervals e_fine / I ~ 3e-4: the ratio is 4.004; tolerance 0.02 is five times that.
TEST(TrapezoidBox, ErrorFallsFourfoldWhenIntervalsDouble) {
  const mcrt::GaussianProduct g{3};
  for (std::uint64_t intervals = 8; intervals <= 64; intervals *= 2) {
    const double coarse = mcrt::trapezoid(g, g.domain(), intervals + 1) - g.reference();
    const double fine = mcrt::trapezoid(g, g.domain(), 2 * intervals + 1) - g.reference();
    EXPECT_NEAR(coarse / fine, 4.0, 0.02) << intervals << " intervals";
  }
}

// The slide's x^3: f''' is constant, so Euler-Maclaurin stops after its first term and
// T_n = x^4/4 |_a^b + h^2/12 (3 b^2 - 3 a^2) exactly.
TEST(Trapezoid1D, CubicMatchesClosedFormAndItsExactError) {
  const mcrt::Cubic cubic;
  EXPECT_DOUBLE_EQ(cubic.reference(), 4.0);  // 2^4 / 4
  const double a = cubic.domain.lower, b = cubic.domain.upper;
  for (std::uint64_t n : {2, 3, 11, 1000}) {
    const double h = (b - a) / static_cast<double>(n - 1);
    const double predicted = cubic.reference() + h * h / 12.0 * (3.0 * b * b - 3.0 * a * a);
    EXPECT_NEAR(mcrt::trapezoid(cubic, cubic.domain, n), predicted, k_roundoff * 10.0) << n;
  }
}

// The slide's x cos x: I = x sin x + cos x |_0^{pi/2} = pi/2 - 1, and the error's leading
// term is h^2/12 (f'(b) - f'(a)) with f' = cos x - x sin x, f'(pi/2) - f'(0) = -pi/2 - 1. The
// next term is O(h^4): at h = pi/200 its relative size is below 1e-4, so (T - I) / lead
// must be within 1e-3 of 1.
TEST(Trapezoid1D, XCosXConvergesToClosedFormWithPredictedError) {
  const mcrt::XCosX f;
  EXPECT_NEAR(f.reference(), mcrt::k_pi / 2.0 - 1.0, 1e-15);
  const std::uint64_t n = 101;
  const double h = f.domain.length() / static_cast<double>(n - 1);
  const double lead = h * h / 12.0 * (-mcrt::k_pi / 2.0 - 1.0);
  EXPECT_NEAR((mcrt::trapezoid(f, f.domain, n) - f.reference()) / lead, 1.0, 1e-3);
}

// The closed forms of J = integral of f^2 that Monte Carlo's variance is checked against,
// checked here against the trapezoid rule on f^2. Its relative error at n = 1001 is
// h^2/12 |(f^2)'(b) - (f^2)'(a)| / J: 3.5e-6 for x^6 on [0,2] (the largest), 3e-7 for
// e^(-2x^2); tolerance 1e-5 relative, while a wrong closed form is off by O(1).
TEST(Integrands, IntegralsOfSquaresMatchQuadrature) {
  const auto check = [](const auto& f) {
    const auto square = [&](double x) { return f(x) * f(x); };
    EXPECT_NEAR(mcrt::trapezoid(square, f.domain, 1001), f.integral_of_square(),
                1e-5 * f.integral_of_square());
  };
  check(mcrt::Gaussian1D{});
  check(mcrt::Cubic{});
  check(mcrt::XCosX{});
  // k = 2 Gaussian product: J = J_1^2, the tensor rule's error twice the 1D one.
  const mcrt::GaussianProduct g{2};
  const auto square = [&](std::span<const double> x) { return g(x) * g(x); };
  EXPECT_NEAR(mcrt::trapezoid(square, g.domain(), 1001), g.integral_of_square(),
              1e-5 * g.integral_of_square());
}

// The fitted slope of log|T - I| against log N over the chapter's kind of grid
// (n = 10 .. 10^5, 8 per decade). Smooth: the error is c / (n - 1)^2 (1 + O(h^2)) and
// N = n, so the local slope is -2 n / (n - 1), between -2.22 at n = 10 and -2 at the end;
// averaged over the grid the fitted slope is -2.01. Tolerance 0.1 covers that bias
// several times over and would reject an O(h) or O(h^3) rule.
TEST(TrapezoidSlopes, SmoothIntegrandConvergesAsNToTheMinusTwo) {
  const mcrt::Gaussian1D g;
  std::vector<double> n_values, errors;
  for (std::uint64_t n : mcrt::log_grid(10, 100000, 8)) {
    n_values.push_back(static_cast<double>(n));
    errors.push_back(std::abs(mcrt::trapezoid(g, g.domain, n) - g.reference()));
  }
  EXPECT_NEAR(mcrt::fit_log_log(n_values, errors).slope, -2.0, 0.1);
}

// ceil(sin x^2) jumps at 0, sqrt(pi) and sqrt(2 pi). The cell holding a jump at fractional
// position theta is off by h (1/2 - theta); the jump at x = 0 always costs h/2. So the error
// is h times a factor between 0 and 3/2 that wanders with n: log error = -log n + noise of
// sd ~ 1, and over 41 grid points spread across 5 decades (sum (log n - mean)^2 ~ 290) the
// slope's scatter is ~ 1/sqrt(290) = 0.06. Tolerance 0.25: four of those, and far from -2.
TEST(TrapezoidSlopes, DiscontinuousIntegrandConvergesAsNToTheMinusOne) {
  const mcrt::CeilSinSquare1D f;
  std::vector<double> n_values, errors;
  for (std::uint64_t n : mcrt::log_grid(10, 1000000, 8)) {
    const double error = std::abs(mcrt::trapezoid(f, f.domain, n) - f.reference());
    if (error == 0.0) continue;  // cannot be fitted in log space
    n_values.push_back(static_cast<double>(n));
    errors.push_back(error);
  }
  ASSERT_GE(n_values.size(), 30u);
  EXPECT_NEAR(mcrt::fit_log_log(n_values, errors).slope, -1.0, 0.25);
}

TEST(TrapezoidGrid, EvaluationCountsAndLargestGridWithinABudget) {
  EXPECT_EQ(mcrt::grid_evaluations(3, 4), 81u);
  EXPECT_EQ(mcrt::grid_evaluations(1u << 20, 4), 0u);  // 2^80 does not fit: reported as 0
  EXPECT_EQ(mcrt::points_per_axis_within(1000000, 3), 100u);
  EXPECT_EQ(mcrt::points_per_axis_within(999999, 3), 99u);
  EXPECT_EQ(mcrt::points_per_axis_within(6561, 8), 3u);
  EXPECT_EQ(mcrt::points_per_axis_within(6560, 8), 2u);
  EXPECT_EQ(mcrt::points_per_axis_within(1000000000, 1), 1000000000u);
  EXPECT_EQ(mcrt::points_per_axis_within(1, 5), 1u);
}

}  // namespace
