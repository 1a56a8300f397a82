#pragma once
// Hypothesis tests for the statistical test suite. Distribution functions come from
// Boost.Math. Each test returns a p-value: the probability, if the code is right, of a result
// at least this far from the closed form. A test rejects when p < alpha, so alpha is its
// false-failure rate.

#include <cstdint>
#include <span>

namespace mcrt::testing {

/// Two-sided z-test: is an estimate with known standard error consistent with `expected`?
/// p = 2 (1 - Phi(|estimate - expected| / standard_error)).
double z_test_p_value(double estimate, double expected, double standard_error);

/// Two-sided one-sample t-test of a sample mean against `expected`, with n - 1 degrees of
/// freedom.
double t_test_p_value(double sample_mean, double sample_variance, std::uint64_t n, double expected);

/// Two-sided chi-square test of a sample variance s^2 of n NORMAL values against the
/// closed-form variance sigma^2: (n - 1) s^2 / sigma^2 ~ chi^2(n - 1), exact at any n. For
/// values that are not normal use variance_z_test_p_value.
double variance_test_p_value(double sample_variance, std::uint64_t n, double expected_variance);

/// THE variance test of the suite: a two-sided z-test of the sample variance s^2 of n i.i.d.
/// values that need not be normal, against sigma^2, given their fourth central moment mu4:
///   Var[s^2] = (mu4 - sigma^4 (n - 3) / (n - 1)) / n,
/// and s^2, a mean of n terms, is normal for large n (thousands: its skewness falls as
/// 1/sqrt(n)), so rejecting at p < alpha has false-failure rate alpha.
double variance_z_test_p_value(double sample_variance, std::uint64_t n, double expected_variance,
                               double fourth_central_moment);

/// The same test when mu4 is not known in closed form: it is taken as kurtosis x sigma^4, the
/// kurtosis m4 / m2^2 estimated from the values themselves. The kurtosis is scale-free, so the
/// standard error does not shrink when s^2 happens to come out low (an estimated mu4 would, and
/// made the test reject too often); it is consistent, so the false-failure rate is alpha for
/// large n, as above. The values must have a finite eighth moment (bounded values do).
double variance_z_test_p_value(std::span<const double> values, double expected_variance);

/// Upper tail P(X > x) of chi-square with `dof` degrees of freedom.
double chi_square_upper_tail(double x, double dof);

/// Standard normal quantile Phi^-1(p), and Student's t quantile with `dof` degrees of freedom.
double normal_quantile(double p);
double student_t_quantile(double p, double dof);

/// Sidak correction: the per-test level that gives family-wise level `alpha` over `tests`
/// independent tests, 1 - (1 - alpha)^(1/tests).
double sidak_alpha(double alpha, int tests);

/// Sidak-adjusted p-value of a family of `tests` independent tests whose smallest p-value is
/// `smallest_p`: 1 - (1 - p_min)^tests. Rejecting it below alpha is rejecting any member below
/// sidak_alpha(alpha, tests); under the null it is Uniform(0,1) again.
double sidak_p_value(double smallest_p, int tests);

/// The Sidak-adjusted p-value of several independent p-values run together.
double sidak_p_value(std::span<const double> p_values);

/// A closed interval [low, high].
struct ConfidenceInterval {
  double low = 0.0;
  double high = 0.0;
  bool contains(double x) const { return low <= x && x <= high; }
};

/// Exact (Clopper-Pearson) two-sided confidence interval at `level` (e.g. 0.99) for a binomial
/// rate, from `successes` out of `trials`. It covers the true rate with probability >= level.
ConfidenceInterval binomial_confidence_interval(std::uint64_t successes, std::uint64_t trials,
                                                double level);

/// Two-sided exact binomial test of `successes` out of `trials` against `rate`:
/// p = min(1, 2 min(P(X <= k), P(X >= k))) with X ~ Binomial(trials, rate).
double binomial_test_p_value(std::uint64_t successes, std::uint64_t trials, double rate);

/// Kolmogorov-Smirnov test that `values` are draws of Uniform(0,1): the statistic
/// D = sup |F_n(x) - x|.
double uniformity_ks_statistic(std::span<const double> values);

/// The p-value P(D_n > d) of the KS statistic for n values. Boost 1.74 has no Kolmogorov
/// distribution, so this is its classical series Q(l) = 2 sum_k (-1)^(k-1) exp(-2 k^2 l^2) at
/// l = (sqrt(n) + 0.12 + 0.11 / sqrt(n)) d (Stephens' correction, accurate to ~1% in p for
/// n >= 5, which is plenty for a calibration run of hundreds of values).
double ks_p_value(double d, std::uint64_t n);

}  // namespace mcrt::testing
