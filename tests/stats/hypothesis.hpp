#pragma once
// Hypothesis tests for the statistical test suite. Distribution functions come from
// Boost.Math. Each test returns a p-value: the probability, if the code is right, of a result
// at least this far from the closed form. A test rejects when p < alpha, so alpha is its
// false-failure rate.

#include <cstdint>

namespace mcrt::stats {

/// Two-sided z-test: is an estimate with known standard error consistent with `expected`?
/// p = 2 (1 - Phi(|estimate - expected| / standard_error)).
double z_test_p_value(double estimate, double expected, double standard_error);

/// Two-sided one-sample t-test of a sample mean against `expected`, with n - 1 degrees of
/// freedom.
double t_test_p_value(double sample_mean, double sample_variance, std::uint64_t n,
                      double expected);

/// Two-sided chi-square test of a sample variance s^2 of n normal values against the
/// closed-form variance sigma^2: (n - 1) s^2 / sigma^2 ~ chi^2(n - 1).
double variance_test_p_value(double sample_variance, std::uint64_t n, double expected_variance);

/// Upper tail P(X > x) of chi-square with `dof` degrees of freedom.
double chi_square_upper_tail(double x, double dof);

/// Standard normal quantile Phi^-1(p), and Student's t quantile with `dof` degrees of freedom.
double normal_quantile(double p);
double student_t_quantile(double p, double dof);

/// Sidak correction: the per-test level that gives family-wise level `alpha` over `tests`
/// independent tests, 1 - (1 - alpha)^(1/tests).
double sidak_alpha(double alpha, int tests);

}  // namespace mcrt::stats
