#pragma once
// The path tracer on the plain layers: estimate_path_radiance's loop, line for line, over a
// closest hit that loops intersect_distance over every primitive and a uniform hemisphere
// sampled with std::cos and std::sin. The fast layers (SphereSet, QuadSet, cos_sin_two_pi)
// must give its images (tests/render/path_tracer_plain_layers_test.cpp) and beat its speed
// (bench_path_tracer's BM_ReferencePathTracer*). It shows a4.1's and a2.1's solutions, so the
// kits that stub them leave it out (scripts/make-assignment WITHHELD_FILES); the closest hit
// it loops over is support/plain_closest_hit.hpp, which every kit keeps.

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "sampling/sampling.hpp"
#include "support/plain_closest_hit.hpp"

namespace mcrt::testing {

inline Color plain_path_radiance(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                 RayCount& count) {
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = plain_closest_hit(scene, ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;
    if (bounce == max_depth) break;
    const Vec2 u = rng.uniform2();
    const double cos_theta = u.x, sin_theta = std::sqrt(std::max(0.0, 1.0 - u.x * u.x));
    const double phi = k_two_pi * u.y;
    const Vec3 local(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
    beta *= material.brdf() * cos_theta / uniform_hemisphere_pdf();
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

}  // namespace mcrt::testing
