#pragma once
/// The error of a render against a reference image, relative to the reference's brightness so
/// that dark and bright regions count alike:
///
///   relative MSE = mean over pixels and channels of (A - R)^2 / (R^2 + 0.01),
///
/// the 0.01 keeping black pixels of R from dominating (a common choice). For an unbiased A and
/// an exact R its expectation is the mean of Var[A] / (R^2 + 0.01), falling as 1/spp.

#include <cmath>
#include <cstddef>

#include "render/image.hpp"

namespace mcrt {

/// Mean over pixels and channels of (A - R)^2 / (R^2 + 0.01); a and reference the same size.
inline double relative_mse(const Image& a, const Image& reference) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[i][c], d = a.pixels[i][c] - r;
      sum += d * d / (r * r + 0.01);
    }
  return sum / (3.0 * static_cast<double>(a.pixels.size()));
}

/// The RMS error against a reference, in the image's own units: sqrt of the mean over pixels
/// and channels of (A - R)^2. Per pixel E[(A - R)^2] = Var[A] + bias[A]^2 + Var[R] for
/// independent A and R, so unlike the two-render estimate it sees A's bias (a depth cut's).
inline double rms_error(const Image& a, const Image& reference) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = a.pixels[i][c] - reference.pixels[i][c];
      sum += d * d;
    }
  return std::sqrt(sum / (3.0 * static_cast<double>(a.pixels.size())));
}

}  // namespace mcrt
