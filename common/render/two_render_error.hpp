#pragma once
/// The error of a render measured without a reference image, from two independent renders A
/// and B of the same estimator at the same spp (disjoint sample streams):
///
///   E[(A - B)^2] = Var[A] + Var[B] = 2 Var[A]   per pixel and channel, for unbiased A and B,
///
/// so mean over pixels and channels of (A - B)^2 / 2 estimates the mean squared error of A.
/// It sees noise only: the bias of a depth cut is the same in A and B and cancels.

#include <cmath>
#include <cstddef>

#include <glm/glm.hpp>

#include "render/image.hpp"

namespace mcrt {

/// Mean over pixels and channels of (A - B)^2 / 2: the mean squared error of A (or of B).
inline double two_render_mean_squared_error(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const Color d = a.pixels[i] - b.pixels[i];
    sum += glm::dot(d, d) / 2.0;
  }
  return sum / (3.0 * static_cast<double>(a.pixels.size()));
}

/// Its square root: the RMS error of one render.
inline double two_render_rms_error(const Image& a, const Image& b) {
  return std::sqrt(two_render_mean_squared_error(a, b));
}

}  // namespace mcrt
