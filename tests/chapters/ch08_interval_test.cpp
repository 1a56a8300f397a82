// Chapter 08's image means carry a 95% confidence interval (mean_with_interval in
// chapters/08_next_event_estimation/shootout.hpp): mean +- 1.96 sqrt(sum_i (A_i - R_i)^2) / n.
// Played against the spread of repeated renders: images A = R + noise of known per-pixel
// standard deviations, many times over, must give intervals whose half-width / 1.96 is the
// standard deviation of their means, and that hold the true mean 95% of the time. (The
// gallery turns the half-width back into a standard error by that same 1.96:
// tests/gallery/lessons_checks_test.py.)

#include <cmath>
#include <cstdint>

#include <fmt/format.h>  // shootout.hpp uses fmt, which chapter 08's main.cpp includes first
#include <gtest/gtest.h>

#include "../../chapters/08_next_event_estimation/shootout.hpp"
#include "core/rng.hpp"

namespace {

using mcrt::Color;
using mcrt::Image;

constexpr int k_width = 48, k_height = 32;
constexpr int k_trials = 2000;

// A standard normal number from two uniform ones (Box-Muller).
double standard_normal(mcrt::Rng& rng) {
  const double u0 = 1.0 - rng.uniform(), u1 = rng.uniform();  // u0 in (0, 1]: log(u0) finite
  return std::sqrt(-2.0 * std::log(u0)) * std::cos(2.0 * 3.14159265358979323846 * u1);
}

TEST(Ch08IntervalTest, HalfWidthIs196StandardErrorsOfTheMeanAndCovers95Percent) {
  // A reference with structure, and per-pixel noise from 0.05 to 0.5 (a render's pixels are
  // unequally noisy): the true mean of every render is the reference's.
  Image reference(k_width, k_height);
  double variance_sum = 0.0;
  std::vector<double> sigma(reference.pixels.size());
  for (std::size_t i = 0; i < reference.pixels.size(); ++i) {
    reference.pixels[i] = Color(0.1 + 0.8 * static_cast<double>(i % 7) / 7.0);
    sigma[i] = 0.05 + 0.45 * static_cast<double>(i % 11) / 10.0;
    variance_sum += sigma[i] * sigma[i];
  }
  const double n = static_cast<double>(reference.pixels.size());
  const double truth = mcrt::mean_radiance(reference);
  const double sd_of_mean = std::sqrt(variance_sum) / n;

  double sum = 0.0, sum_squares = 0.0, half_width_sum = 0.0;
  int covered = 0;
  for (int t = 0; t < k_trials; ++t) {
    mcrt::Rng rng(48, mcrt::stream_index(1, static_cast<std::uint64_t>(t)));
    Image render = reference;
    for (std::size_t i = 0; i < render.pixels.size(); ++i)
      render.pixels[i] += Color(sigma[i] * standard_normal(rng));  // grey noise: average() keeps it
    const mcrt::MeanWithInterval m = mcrt::mean_with_interval(render, reference);
    sum += m.mean;
    sum_squares += m.mean * m.mean;
    half_width_sum += m.half_width;
    covered += std::abs(m.mean - truth) <= m.half_width ? 1 : 0;
  }
  const double mean_of_means = sum / k_trials;
  const double spread =
      std::sqrt((sum_squares - k_trials * mean_of_means * mean_of_means) / (k_trials - 1));
  const double standard_error = half_width_sum / k_trials / 1.96;
  // The spread of 2000 means is known to a relative 1/sqrt(2 x 2000) = 1.6%; 8% is 5 of those.
  // A 99.9% interval's 3.29 would make the ratio 1.68, a 68% interval's 1.00 would make it 0.51.
  EXPECT_NEAR(spread / sd_of_mean, 1.0, 0.08);
  EXPECT_NEAR(standard_error / sd_of_mean, 1.0, 0.08);
  EXPECT_NEAR(standard_error / spread, 1.0, 0.08);
  // Coverage: binomial(2000, 0.95) has sd 0.0049; +-0.025 is 5 of them (a 99.9% interval would
  // cover 0.999, a 90% one 0.90).
  EXPECT_NEAR(static_cast<double>(covered) / k_trials, 0.95, 0.025);
}

}  // namespace
