#pragma once
// A fixed batch of rays that real paths meet, for benchmarks of closest-hit queries alone.

#include <cstdint>
#include <optional>
#include <vector>

#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "geometry/hit.hpp"
#include "render/scene.hpp"
#include "sampling/sampling.hpp"

namespace mcrt::bench {

/// The camera rays of a 64x48 image of `scene` and up to 3 uniform bounces after each.
inline std::vector<Ray> path_rays(const Scene& scene) {
  const Camera camera(scene.camera, 64, 48);
  std::vector<Ray> rays;
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      Rng rng(7, stream_index(static_cast<std::uint64_t>(y) * 64 + x, 0));
      Ray ray = camera.generate_ray(x, y, rng.uniform2());
      for (int bounce = 0; bounce <= 3; ++bounce) {
        rays.push_back(ray);
        const std::optional<Hit> hit = scene.closest_hit(ray);
        if (!hit) break;
        const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
        ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
      }
    }
  return rays;
}

}  // namespace mcrt::bench
