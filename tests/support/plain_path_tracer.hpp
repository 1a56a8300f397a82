#pragma once
// The path tracer on the plain layers: estimate_path_radiance's loop, line for line, over a
// closest hit that loops intersect_distance over every primitive and a uniform hemisphere
// sampled with std::cos and std::sin. The fast layers (SphereSet, QuadSet, cos_sin_two_pi)
// must give its images (tests/plain_layers_test.cpp) and beat its speed
// (bench_path_tracer's BM_ReferencePathTracer*); plain_closest_hit is also the reference of
// tests/closest_hit_test.cpp.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "sampling/sampling.hpp"

namespace mcrt::testing {

/// The nearest hit in `range` by one intersect_distance per primitive, spheres first; the
/// first strictly nearer hit wins, as in Scene::closest_hit.
inline std::optional<Hit> plain_closest_hit(const Scene& scene, const Ray& ray,
                                            Interval range = {}) {
  std::optional<Hit> hit;
  for (const Sphere& s : scene.spheres())
    if (const auto t = intersect_distance(s, ray, range)) {
      range.max = *t;
      hit = hit_at(s, ray, *t);
    }
  for (std::size_t i = 0; i < scene.quads().size(); ++i)
    if (const auto t = intersect_distance(scene.quads()[i], ray, range)) {
      range.max = *t;
      hit = hit_at(scene.quads()[i], ray, *t);
      hit->material = scene.quad_face_material(i, ray.direction);  // a one-sided lamp's back
    }
  return hit;
}

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
