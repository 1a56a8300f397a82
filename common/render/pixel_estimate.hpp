#pragma once
/// One pixel's estimate: the lecture's "for each sample: shoot a ray through a random point of
/// the pixel, trace it, average".
///
/// The pixel's value is an integral over its area A (pixel units, A = 1):
///   I = integral over the pixel of L(ray(x + u_x, y + u_y)) du,   u uniform in [0,1)^2,
/// and its estimate is the mean of spp samples, each at its own jittered u:
///   I_N = (1/N) sum_i L_i,   E[I_N] = I,   Var[I_N] = sigma^2 / N   (N = spp),
/// with sigma^2 the variance of one sample (of the jitter and of the tracer's own randomness
/// together). The standard error estimates sqrt(Var[I_N]) from the samples themselves:
///   se = sqrt(s^2 / N),   s^2 = (1/(N-1)) sum_i (Y_i - Y_bar)^2   (unbiased: E[s^2] = sigma^2),
/// where Y_i = average(L_i), the channel mean: the mean is per channel, the standard error is
/// that of the channel-mean radiance (the one number per sample the region tests compare).

#include <cmath>

#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "core/math.hpp"

namespace mcrt {

/// The mean radiance of a pixel's samples and the standard error of its channel mean.
struct PixelEstimate {
  Color mean{0.0};
  double standard_error = 0.0;
};

/// The estimate of pixel (x, y) from spp >= 2 samples: for each sample, u = rng.uniform2()
/// (uniform in [0,1)^2), the ray camera.generate_ray(x, y, u), its radiance
/// radiance(ray, rng) (a Color; it may draw from rng after u). Returns the per-channel mean
/// and sqrt(s^2 / spp), s^2 the unbiased sample variance of average(radiance).
template <class Radiance>
PixelEstimate estimate_pixel(const Camera& camera, int x, int y, int spp, Radiance&& radiance,
                             Rng& rng) {
  // ASSIGNMENT a4.2 BEGIN stub: (void)camera; (void)x; (void)y; (void)spp; (void)radiance; (void)rng; NOT_IMPLEMENTED(estimate_pixel);
  // Welford's running mean and sum of squared deviations of the channel mean: no
  // cancellation when the mean is large against the spread.
  double mean = 0.0, squares = 0.0;
  Color sum(0.0);
  for (int sample = 1; sample <= spp; ++sample) {
    const Vec2 u = rng.uniform2();  // a jittered point of the pixel
    const Color L = radiance(camera.generate_ray(x, y, u), rng);
    sum += L;
    const double value = average(L), delta = value - mean;
    mean += delta / sample;
    squares += delta * (value - mean);
  }
  const double n = spp;
  const double sample_variance = squares / (n - 1.0);  // unbiased: divided by N - 1
  return {sum / n, std::sqrt(sample_variance / n)};
  // ASSIGNMENT a4.2 END
}

}  // namespace mcrt
