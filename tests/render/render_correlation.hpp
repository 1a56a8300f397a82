#pragma once
// Correlation between Monte Carlo samples that must be independent, as p-values; shared by
// tests/render/render_correlation_checks.cpp and the unit test that shows they reject correlated
// streams (tests/render/render_correlation_known_bugs.hpp).
//
// For independent values x_i, y_i with known mean mu and variance sigma^2, the standardised
// products (x_i - mu)(y_i - mu) / sigma^2 have mean 0 and variance 1, so over n pairs
//   Z = sum of products / sqrt(n)  ~  N(0, 1)   (central limit theorem; the values are bounded).
// Statistics over different pairings (left neighbour, upper neighbour, ...) are uncorrelated
// under independence (E[x1 x2 x1 x3] = sigma^2 E[x2] E[x3] = 0), so the sum of their squares
// is chi-square with as many degrees of freedom as statistics. Correlation inflates it.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "stats/hypothesis.hpp"

namespace mcrt::testing {

/// Sum of squares of the Z statistics and how many there are.
struct ChiSquareSum {
  double chi2 = 0.0;
  int dof = 0;
  void add(double product_sum, double pairs) {
    const double z = product_sum / std::sqrt(pairs);
    chi2 += z * z;
    ++dof;
  }
  double p_value() const { return chi_square_upper_tail(chi2, dof); }
};

/// Standardised values (x - mu) / sigma.
inline std::vector<double> standardised(const std::vector<double>& values, double mean,
                                        double variance) {
  std::vector<double> z(values.size());
  const double inverse_sigma = 1.0 / std::sqrt(variance);
  for (std::size_t i = 0; i < values.size(); ++i) z[i] = (values[i] - mean) * inverse_sigma;
  return z;
}

/// One image of one sample per pixel (row-major, row 0 at the top): correlation of each pixel
/// with its right, lower, lower-right and lower-left neighbours; chi-square with 4 dof.
inline double neighbour_correlation_p_value(const std::vector<double>& values, int width,
                                            int height, double mean, double variance) {
  const std::vector<double> z = standardised(values, mean, variance);
  auto at = [&](int x, int y) {
    return z[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
             static_cast<std::size_t>(x)];
  };
  ChiSquareSum sum;
  const int offsets[4][2] = {{1, 0}, {0, 1}, {1, 1}, {-1, 1}};
  for (const auto& offset : offsets) {
    double products = 0.0, pairs = 0.0;
    for (int y = 0; y + offset[1] < height; ++y)
      for (int x = std::max(0, -offset[0]); x < width && x + offset[0] < width; ++x) {
        products += at(x, y) * at(x + offset[0], y + offset[1]);
        pairs += 1.0;
      }
    sum.add(products, pairs);
  }
  return sum.p_value();
}

/// Several images of the same pixels, image s holding sample s of every pixel: correlation of
/// every pair of samples of a pixel; chi-square with S (S - 1) / 2 dof.
inline double sample_correlation_p_value(const std::vector<std::vector<double>>& samples,
                                         double mean, double variance) {
  std::vector<std::vector<double>> z;
  for (const auto& image : samples) z.push_back(standardised(image, mean, variance));
  ChiSquareSum sum;
  for (std::size_t a = 0; a < z.size(); ++a)
    for (std::size_t b = a + 1; b < z.size(); ++b) {
      double products = 0.0;
      for (std::size_t i = 0; i < z[a].size(); ++i) products += z[a][i] * z[b][i];
      sum.add(products, static_cast<double>(z[a].size()));
    }
  return sum.p_value();
}

}  // namespace mcrt::testing
