#pragma once
/// Images of the recursive estimator: the pixel loop (render/render.hpp) with every camera
/// sample estimated as incidentRadiance(camera ray) at depth 0 (render/recursive_estimator.hpp).
/// A renderer keeps the total work of its renders, and its progress bar counts each sample's
/// predicted rays (max_rays_per_sample), so the bar moves with the work however N and k grow.

#include <cstdint>

#include "core/progress.hpp"
#include "geometry/camera.hpp"
#include "render/recursive_estimator.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

namespace mcrt {

struct RecursiveRenderer {
  const Scene& scene;
  const Camera& camera;
  std::uint64_t seed = 1;
  int threads = 1;
  ProgressBar* progress = nullptr;  ///< advanced by each sample's predicted rays, if given
  RenderTotals total;               ///< the work of every render so far

  /// An image of `spp` samples per pixel, sample indices [first_sample, first_sample + spp).
  RenderResult operator()(const RecursiveSettings& recursion, int spp,
                          std::uint64_t first_sample = 0) {
    const std::uint64_t sample_rays = max_rays_per_sample(recursion.branching, recursion.max_depth);
    const RenderSettings settings{spp, first_sample, seed, threads, nullptr};
    RenderResult result = render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
      const Color L = incident_radiance(scene, ray, 0, recursion, rng, count);
      if (progress) progress->advance(sample_rays);
      return L;
    });
    total.add(result);
    return result;
  }
};

}  // namespace mcrt
