#pragma once
// Known-wrong ways of meeting a delta material (render/specular.hpp), each one mistake, kept so
// that tests/render/specular_test.cpp can show the comparison with the independent renderer of
// smallpt's scene (render/scene_sphere_box_reference.hpp) rejects them.

#include <optional>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "render/light_sampling.hpp"
#include "render/next_event_estimation.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt::testing {

/// Wrong: NEE that follows mirrors and glass but adds Le only for the eye's own hit, as if a
/// light sample had already counted the light seen after a delta. No light sample can aim
/// along a delta's direction, so the light's image in the mirror and the caustic under the
/// glass ball are lost.
inline Color nee_without_light_after_delta(const Scene& scene, Ray ray, Rng& rng, RayCount& count) {
  const PathEnd end{Roulette{}, -1};
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    if (bounce == 0) radiance += material.emission;  // the mistake: nothing after a delta
    if (bounce >= end.roulette.min_depth) {
      const double q = survival_probability(end.roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }
    const Vec3 wo = -ray.direction;
    if (material.is_delta()) {
      const BsdfSample specular = sample_delta(material, *hit, wo, rng.uniform());
      beta *= specular.weight;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }
    const DirectSample light = sample_direct_light(scene, *hit, rng, count);
    if (light.contributes())
      radiance +=
          beta * material.f_r(light.wi, wo, hit->normal) * light.le * light.cos_x / light.pdf_light;
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    if (!(local.z > 0.0)) break;
    beta *= cosine_bounce_weight(material, Frame(hit->normal).to_world(local), wo, hit->normal);
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

/// Wrong: a path tracer that treats the mirror and the glass as diffuse surfaces of albedo
/// `tint` (what cornell-spheres does on purpose): smallpt's image it is not.
inline Color path_with_deltas_as_diffuse(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                         RayCount& count) {
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;
    if (bounce == max_depth) break;
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    if (!(local.z > 0.0)) break;
    beta *= material.is_delta() ? material.tint : material.albedo;  // cosine: f_r cos / p = rho
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

}  // namespace mcrt::testing
