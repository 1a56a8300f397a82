#pragma once
/// The image loop with a choice of sampler (--sampler): render() of render/render.hpp when the
/// sampler is independent (the same image, bit for bit), else each pixel's spp samples as the
/// points of padded 2D sets (sampling/path_sampler.hpp): sample s of pixel p is
/// PaddedSample(pixel, s) of the pixel's PaddedPixel(kind, key(seed, p, first_sample), spp),
/// which makes each set's keys once for all the pixel's samples; its first 2D point is the
/// position in the pixel, the next ones the estimator's.
///
/// The estimator is a generic callable `Color(const Ray&, auto& uniforms, RayCount&)`, called
/// with an Rng or a PaddedSample, both inlined. Every sample is a pure function of (seed,
/// pixel, first_sample, s): the image does not depend on the thread count.

#include <cstdint>

#include "render/render.hpp"
#include "sampling/path_sampler.hpp"

namespace mcrt {

template <class Estimator>
RenderResult render_sampled(const Camera& camera, const RenderSettings& settings,
                            PathSampler sampler, Estimator&& estimate) {
  if (sampler == PathSampler::independent) return render(camera, settings, estimate);
  const auto spp = static_cast<std::uint32_t>(settings.spp);
  return render_rows(
      camera, settings, [&](int y, Color* row, RayCount& rays, std::uint64_t& non_finite) {
        for (int x = 0; x < camera.width(); ++x) {
          const std::uint64_t pixel = static_cast<std::uint64_t>(y) * camera.width() + x;
          PaddedPixel padded(sampler,
                             PaddedPixel::pixel_key(settings.seed, pixel, settings.first_sample),
                             spp);
          Color sum(0.0);
          for (std::uint32_t s = 0; s < spp; ++s) {
            PaddedSample sample(padded, s);
            const Ray ray = camera.generate_ray(x, y, sample.uniform2());  // set 0: the pixel
            const Color radiance = estimate(ray, sample, rays);
            if (!is_finite(radiance)) ++non_finite;
            sum += radiance;
          }
          row[x] = sum / static_cast<double>(settings.spp);
        }
      });
}

}  // namespace mcrt
