#pragma once
/// The image loop every renderer shares: for each pixel, for each sample, a camera ray
/// through a jittered point of the pixel, an estimate of its radiance, the average.
///
/// The estimator is a callable `Color(const Ray&, Rng&, RayCount&)`; it is inlined, so the hot
/// loop has no virtual call. Sample s of pixel p draws from stream (p, s) of the seed, so the
/// image does not depend on the thread count, and renders with disjoint sample ranges
/// (`first_sample`) are independent.

#include <chrono>
#include <cstdint>
#include <vector>

#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/image.hpp"

namespace mcrt {

struct RenderSettings {
  int spp = 1;                     ///< samples per pixel
  std::uint64_t first_sample = 0;  ///< sample indices [first_sample, first_sample + spp)
  std::uint64_t seed = 1;
  int threads = 1;
  ProgressBar* progress = nullptr;  ///< advanced by one per finished row, if given
};

struct RenderResult {
  Image image;
  std::uint64_t rays = 0;
  std::uint64_t non_finite_samples = 0;  ///< NaN or infinite estimates (kept, and counted)
  double seconds = 0.0;
  double rays_per_second() const {
    return seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0;
  }
};

/// The frame every image loop shares: the rows in parallel, row y traced by
/// trace_row(y, row, rays, non_finite), which writes the row's `width` pixels at `row` and
/// counts its rays and non-finite estimates (in locals of its own thread, stored once per row);
/// the totals summed, the time taken, the progress bar advanced by a row at a time.
template <class TraceRow>
RenderResult render_rows(const Camera& camera, const RenderSettings& settings,
                         TraceRow&& trace_row) {
  const auto start = std::chrono::steady_clock::now();
  const int height = camera.height();
  RenderResult result;
  result.image = Image(camera.width(), height);
  std::vector<RayCount> row_rays(height);
  std::vector<std::uint64_t> row_non_finite(height, 0);

  parallel_for(static_cast<std::size_t>(height), settings.threads, [&](std::size_t row) {
    const int y = static_cast<int>(row);
    RayCount rays;
    std::uint64_t non_finite = 0;
    trace_row(y, &result.image.at(0, y), rays, non_finite);
    row_rays[row] = rays;
    row_non_finite[row] = non_finite;
    if (settings.progress) settings.progress->advance();
  });

  for (int y = 0; y < height; ++y) {
    result.rays += row_rays[y].rays;
    result.non_finite_samples += row_non_finite[y];
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

template <class Estimator>
RenderResult render(const Camera& camera, const RenderSettings& settings, Estimator&& estimate) {
  return render_rows(camera, settings,
                     [&](int y, Color* row, RayCount& rays, std::uint64_t& non_finite) {
                       for (int x = 0; x < camera.width(); ++x) {
                         const std::uint64_t pixel =
                             static_cast<std::uint64_t>(y) * camera.width() + x;
                         Color sum(0.0);
                         for (int s = 0; s < settings.spp; ++s) {
                           Rng rng(settings.seed, stream_index(pixel, settings.first_sample + s));
                           const Ray ray = camera.generate_ray(x, y, rng.uniform2());
                           const Color radiance = estimate(ray, rng, rays);
                           if (!is_finite(radiance)) ++non_finite;
                           sum += radiance;
                         }
                         row[x] = sum / static_cast<double>(settings.spp);
                       }
                     });
}

}  // namespace mcrt
