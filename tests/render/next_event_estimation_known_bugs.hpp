#pragma once
// Known-wrong next-event estimators and MIS, each the chapter's loop with one mistake, kept so
// the tests can show the checks' procedures (render/next_event_estimation_procedures.hpp) reject them
// (tests/render/next_event_estimation_test.cpp). Same signature as render/next_event_estimation.hpp's estimators, with
// the path end given as a depth cut (Russian roulette as there).

#include <optional>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "render/light_sampling.hpp"
#include "render/mis.hpp"
#include "render/next_event_estimation.hpp"
#include "render/scene.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt::testing {

/// The mistakes the shell below can make, one at a time.
struct NeeMistake {
  bool no_jacobian = false;        ///< p_w taken as p_A: cos(theta_y) / r^2 left out
  bool emission_twice = false;     ///< BSDF-sampled hits on lights add Le as well
  bool shadow_hits_light = false;  ///< the shadow ray's range includes the light point itself
  bool light_from_behind = false;  ///< |cos(theta_y)| and Le of a one-sided light's back
  bool cap_only = false;         ///< a sphere light sampled on its cap from everywhere (the cap is
                                 ///< all the room sees, but not all a point outside the room sees)
  bool one_light_pdf = false;    ///< the pick of one of N lights left out of the pdf (no 1/N)
  bool no_cos_y = false;         ///< p_w taken as p_A r^2: the light's cos(theta_y) left out
  bool cut_after_light = false;  ///< the depth cut checked after the light sample, not before
};

/// A light sample with the mistake's way of tracing the shadow ray and converting the pdf.
inline DirectSample wrong_direct_light(const Scene& scene, const Hit& hit, Rng& rng,
                                       RayCount& count, const NeeMistake& m) {
  DirectSample d;
  const double u_pick = rng.uniform();
  const Vec2 u = rng.uniform2();
  const std::size_t n = scene.emitters().size();
  const Emitter& e =
      scene.emitters()[std::min(n - 1, static_cast<std::size_t>(u_pick * static_cast<double>(n)))];
  const Vec3 x = spawn_ray(hit, hit.normal).origin;
  const Sphere* sphere = e.kind == Emitter::sphere ? &scene.spheres()[e.index] : nullptr;
  const LightPoint y = m.cap_only && sphere ? sample_sphere_cap(sphere->center, sphere->radius,
                                                                e.cap_axis, e.cap_height, u)
                                            : sample_emitter(scene, e, x, u);
  const auto [shadow_ray, distance] = spawn_ray_to(hit, y.point);
  d.wi = shadow_ray.direction;
  d.cos_x = glm::dot(hit.normal, d.wi);
  const double cos_y = glm::dot(y.normal, -d.wi);
  d.le = m.light_from_behind ? scene.emitted(e, cos_y >= 0.0 ? y.normal : -y.normal, -d.wi)
                             : scene.emitted(e, y.normal, -d.wi);
  if (d.cos_x <= 0.0 || d.le == Color(0.0)) return d;
  const double p_area = m.one_light_pdf ? y.pdf_area : y.pdf_area / static_cast<double>(n);
  d.pdf_light =
      m.no_jacobian ? p_area : area_to_solid_angle_pdf(p_area, distance, m.no_cos_y ? 1.0 : cos_y);
  ++count.rays;
  const double end = m.shadow_hits_light ? distance * (1.0 + k_shadow_ray_shortening)
                                         : distance * (1.0 - k_shadow_ray_shortening);
  d.visible = !scene.any_hit(shadow_ray, {1e-9, end});
  return d;
}

/// The NEE loop of estimate_nee_radiance with mistake m.
inline Color wrong_nee_radiance(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                RayCount& count, const NeeMistake& m) {
  const PathEnd end{Roulette{}, max_depth};
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    if (bounce == 0 || m.emission_twice) radiance += beta * material.emission;
    if (!m.cut_after_light && end.cut_at(bounce)) break;
    // (cut after the light sample: no roulette at the last vertex, as under the grader's
    // PathEnd, which has none, so that only the light sample is one too many)
    if (bounce >= end.roulette.min_depth && !(m.cut_after_light && end.cut_at(bounce))) {
      const double q = survival_probability(end.roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }
    const DirectSample light = wrong_direct_light(scene, *hit, rng, count, m);
    if (light.contributes())
      radiance += beta * material.brdf() * light.le * light.cos_x / light.pdf_light;
    if (m.cut_after_light && end.cut_at(bounce)) break;
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    if (!(local.z > 0.0)) break;
    beta *= material.albedo;
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

/// Wrong: the light sample divided by p_A, not p_w = p_A r^2 / cos(theta_y).
inline Color nee_without_jacobian(const Scene& scene, Ray ray, int depth, Rng& rng, RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.no_jacobian = true});
}

/// Wrong: a BSDF-sampled ray that hits a light adds its Le too, which the shadow ray counted.
inline Color nee_emission_twice(const Scene& scene, Ray ray, int depth, Rng& rng, RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.emission_twice = true});
}

/// Wrong: the shadow ray runs up to the light point, so the light itself blocks it.
inline Color nee_shadow_ray_hits_light(const Scene& scene, Ray ray, int depth, Rng& rng,
                                       RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.shadow_hits_light = true});
}

/// Wrong: the light's cos(theta_y) left out of p_w = p_A r^2 / cos(theta_y): every light sample
/// is weighted by an extra cos(theta_y) <= 1, darker the more obliquely the light is seen.
inline Color nee_without_cos_y(const Scene& scene, Ray ray, int depth, Rng& rng, RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.no_cos_y = true});
}

/// Wrong: the path cut at depth k after the light sample of its last vertex, not before: that
/// sample's light has travelled k + 1 segments, one bounce more than the depth allows.
inline Color nee_cut_after_light_sample(const Scene& scene, Ray ray, int depth, Rng& rng,
                                        RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.cut_after_light = true});
}

/// Wrong: a one-sided light lights what is behind it (|cos(theta_y)|, Le of its back).
inline Color nee_light_from_behind(const Scene& scene, Ray ray, int depth, Rng& rng, RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.light_from_behind = true});
}

/// Wrong: a sphere light sampled on the cap its enclosure leaves visible, from every point,
/// inside the enclosure or not (the sampler chapter 08 first shipped): paths that start above
/// cornell-spheres' ceiling see the light outside the cap and get no direct light from it.
inline Color nee_cap_only(const Scene& scene, Ray ray, int depth, Rng& rng, RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.cap_only = true});
}

/// Wrong: the pick of one of N lights left out of the pdf (p_A for p_A / N): with N lights the
/// direct light is divided by N. Invisible with one light.
inline Color nee_without_one_over_n_lights(const Scene& scene, Ray ray, int depth, Rng& rng,
                                           RayCount& c) {
  return wrong_nee_radiance(scene, ray, depth, rng, c, {.one_light_pdf = true});
}

/// Wrong: MIS whose weights do not sum to 1: balance for the light sample, power for the BSDF
/// sample (w_l + w_b < 1 wherever the pdfs differ).
inline Color mis_weights_not_summing_to_one(const Scene& scene, Ray ray, int max_depth, Rng& rng,
                                            RayCount& count) {
  const PathEnd end{Roulette{}, max_depth};
  Color radiance(0.0), beta(1.0);
  double pdf_bsdf = 0.0;
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    if (material.is_emitter()) {
      const double w_b = bounce == 0 ? 1.0
                                     : mis_weight(MisHeuristic::power, pdf_bsdf,
                                                  light_pdf_towards(scene, ray, *hit));
      radiance += beta * w_b * material.emission;
    }
    if (end.cut_at(bounce)) break;
    if (bounce >= end.roulette.min_depth) {
      const double q = survival_probability(end.roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }
    const DirectSample light = sample_direct_light(scene, *hit, rng, count);
    if (light.contributes())
      radiance +=
          beta *
          mis_weight(MisHeuristic::balance, light.pdf_light, cosine_hemisphere_pdf(light.cos_x)) *
          material.brdf() * light.le * light.cos_x / light.pdf_light;
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    pdf_bsdf = cosine_hemisphere_pdf(local.z);
    if (!(pdf_bsdf > 0.0)) break;
    beta *= material.albedo;
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

}  // namespace mcrt::testing
