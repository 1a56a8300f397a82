#pragma once
// Known-wrong path tracers, each the chapter's path loop with one mistake, kept so the tests
// can show the furnace check (render/path_tracer_furnace.hpp) rejects them
// (tests/render/path_tracer_test.cpp). Same signature as estimate_path_radiance.

#include <optional>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt::testing {

/// The path loop L = sum beta Le, beta *= weight(f_r, local direction), with the local
/// direction drawn by sample(u): the shell every wrong tracer below fills with its mistake.
template <class Sample, class Weight>
Color path_radiance_with(const Scene& scene, Ray ray, int max_depth, Rng& rng, RayCount& count,
                         Sample sample, Weight weight) {
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    radiance += beta * scene.material(*hit).emission;
    if (bounce == max_depth) break;
    const Vec3 local = sample(rng.uniform2());
    beta *= weight(scene.material(*hit).brdf(), local);
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

/// Wrong: the path weight misses cos(theta_i), beta *= f_r / p: each bounce weighs 2a, not a.
inline Color path_radiance_without_cosine(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                          RayCount& count) {
  return path_radiance_with(scene, ray, max_depth, rng, count, sample_uniform_hemisphere,
                            [](Color f_r, Vec3) { return f_r / uniform_hemisphere_pdf(); });
}

/// Wrong: hemisphere directions divided by the whole sphere's pdf 1/(4 pi): a factor 2 high.
inline Color path_radiance_with_sphere_pdf(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                           RayCount& count) {
  return path_radiance_with(scene, ray, max_depth, rng, count, sample_uniform_hemisphere,
                            [](Color f_r, Vec3 w) { return f_r * w.z / (0.25 * k_inv_pi); });
}

/// Wrong: cosine-weighted directions divided by the uniform pdf 1/(2 pi) instead of cos / pi.
inline Color path_radiance_cosine_directions_uniform_pdf(const Scene& scene, Ray ray, int max_depth,
                                                         Rng& rng, RayCount& count) {
  return path_radiance_with(scene, ray, max_depth, rng, count, sample_cosine_hemisphere,
                            [](Color f_r, Vec3 w) { return f_r * w.z / uniform_hemisphere_pdf(); });
}

}  // namespace mcrt::testing
