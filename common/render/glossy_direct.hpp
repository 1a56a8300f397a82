#pragma once
/// Direct light reflected by a glossy (Phong) surface towards the eye, in Veach's plates
/// (render/veach_plates.hpp), by four strategies. At a plate point x seen from wo:
///
///   L_r(x, wo) = integral over directions w of f(w, wo) Le(w) cos(theta_w) dw,
///
/// Le(w) the radiance of the first thing met along w (a light's, or 0). Each one-sample
/// estimator below has E = L_r; they differ in where their variance goes.
///
/// The light-sampling pdf of a direction. One light is picked with probability 1/N, then a
/// direction uniform in the cone it subtends from x (sampling/light.hpp). So the density of a
/// direction w is the mixture
///   p_l(w) = sum over lights i whose cone holds w of (1/N) p_cone_i,
/// a sum because cones may overlap (one light behind another): whichever light w meets first,
/// every light whose cone holds w could have drawn it. In this scene the cones are disjoint and
/// the sum has one term, (1/N) p_cone of the light w hits; the code keeps the general form.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/mis.hpp"
#include "render/veach_plates.hpp"
#include "sampling/light.hpp"
#include "sampling/phong.hpp"

namespace mcrt {

/// The strategies of the figure, in its order.
enum class GlossyStrategy { light, bsdf, mis_balance, mis_power };

/// p_l(w) at x (see the top of this file); `drawn_from` is the light the direction was drawn
/// from, if it was: its cone holds w by construction, whatever round-off says at the rim.
inline double plates_light_pdf(const VeachPlates& scene, const Vec3& x, const Vec3& w,
                               std::size_t drawn_from = static_cast<std::size_t>(-1)) {
  const double pick = 1.0 / static_cast<double>(scene.light_count());
  double pdf = 0.0;
  for (std::size_t i = 0; i < scene.light_count(); ++i) {
    const Sphere& s = scene.lights[i];
    // w is in the cone of sphere i iff the line x + t w (t > 0) meets it (x outside it).
    if (i == drawn_from ||
        intersect_distance(s, Ray(x, w), {0.0, std::numeric_limits<double>::infinity()})) {
      pdf += pick * sphere_cone_pdf_solid_angle(s.center, s.radius, x);
    }
  }
  return pdf;
}

/// What a ray from the plate point meets: Le of the first light along it, 0 if a plate or
/// nothing comes first. One ray, counted.
inline double traced_emission(const VeachPlates& scene, const Ray& ray, RayCount& count) {
  ++count.rays;
  const std::optional<Hit> hit = closest_hit(scene, ray);
  return hit && scene.is_light(*hit) ? scene.radiance[scene.light_index(*hit)] : 0.0;
}

/// One sample of each strategy at a plate hit: its contribution f Le cos / p, and both pdfs
/// of its direction, so that MIS can weight it.
struct GlossySample {
  double f_le_cos = 0.0;  ///< f(w, wo) Le(w) cos(theta_w)
  double pdf_light = 0.0;
  double pdf_bsdf = 0.0;
};

/// Light sampling: light j with probability 1/N, w uniform in its cone, a shadow ray along w.
inline GlossySample draw_light_sample(const VeachPlates& scene, const Hit& hit, const Vec3& wo,
                                      Rng& rng, RayCount& count) {
  // ASSIGNMENT a6.3 BEGIN stub: (void)scene; (void)hit; (void)wo; (void)rng; (void)count; NOT_IMPLEMENTED(draw_light_sample);
  const Phong& material = scene.materials[hit.material];
  const std::size_t j = rng.uniform_below(static_cast<std::uint32_t>(scene.light_count()));
  const Sphere& light = scene.lights[j];
  const LightPoint y = sample_sphere_cone(light.center, light.radius, hit.point, rng.uniform2());
  const Vec3 w = glm::normalize(y.point - hit.point);
  GlossySample s;
  s.pdf_light = plates_light_pdf(scene, hit.point, w, j);
  s.pdf_bsdf = phong_pdf(material, w, hit.normal, wo);
  // Traced even when f = 0 (w below the plate): every sample costs the same rays, so equal
  // samples are equal rays for every strategy.
  const double le = traced_emission(scene, spawn_ray(hit, w), count);
  s.f_le_cos =
      phong_brdf(material, w, wo, hit.normal) * le * std::max(0.0, glm::dot(w, hit.normal));
  return s;
  // ASSIGNMENT a6.3 END
}

/// BSDF sampling: w from the Phong material (lobe round the mirror direction, or cosine for
/// its diffuse part), a ray along w to see which light, if any, it meets.
inline GlossySample draw_bsdf_sample(const VeachPlates& scene, const Hit& hit, const Vec3& wo,
                                     Rng& rng, RayCount& count) {
  const Phong& material = scene.materials[hit.material];
  const Vec3 w = sample_phong(rng.uniform2(), material, hit.normal, wo);
  GlossySample s;
  s.pdf_bsdf = phong_pdf(material, w, hit.normal, wo);
  s.pdf_light = plates_light_pdf(scene, hit.point, w);
  // Traced even below the plate (f = 0 there): the same rays per sample as light sampling.
  const double le = traced_emission(scene, spawn_ray(hit, w), count);
  s.f_le_cos =
      phong_brdf(material, w, wo, hit.normal) * le * std::max(0.0, glm::dot(w, hit.normal));
  return s;
}

/// f Le cos / p, 0 where the sample carries nothing (f Le cos = 0, whatever p).
inline double sample_value(double f_le_cos, double pdf) {
  return f_le_cos > 0.0 && pdf > 0.0 ? f_le_cos / pdf : 0.0;
}

/// Light sampling alone: Y = f Le cos / p_l(w).
/// E[Y] = L_r: p_l > 0 wherever Le > 0 (every direction that meets a light is in its cone).
/// Var[Y] is small where f is flat over the cone (a rough plate: f Le cos / p_l ~ const per
/// light), huge where f is a spike much narrower than the cone (a sharp plate and a large
/// light: most samples miss the lobe and give ~0, a few give f_peak Le cos / p_l).
inline double estimate_light_sampling(const VeachPlates& scene, const Hit& hit, const Vec3& wo,
                                      Rng& rng, RayCount& count) {
  const GlossySample s = draw_light_sample(scene, hit, wo, rng, count);
  return sample_value(s.f_le_cos, s.pdf_light);
}

/// BSDF sampling alone: Y = f Le cos / p_b(w).
/// E[Y] = L_r: p_b > 0 wherever f > 0 (the lobe's pdf covers the lobe, the cosine part the
/// hemisphere). For the lobe alone Y = rho_s (m + 2)/(m + 1) cos Le or 0: small variance when
/// a light fills the lobe (sharp plate, large light), a rare jackpot when a small light covers
/// a sliver of a wide lobe (Var ~ Le^2 times the hit probability, which falls as r^2 while
/// Le^2 grows as 1/r^4: variance ~ 1/r^2).
inline double estimate_bsdf_sampling(const VeachPlates& scene, const Hit& hit, const Vec3& wo,
                                     Rng& rng, RayCount& count) {
  const GlossySample s = draw_bsdf_sample(scene, hit, wo, rng, count);
  return sample_value(s.f_le_cos, s.pdf_bsdf);
}

/// MIS, one sample of each strategy (render/mis.hpp):
///   Y = w_l(w1) f Le cos / p_l(w1) + w_b(w2) f Le cos / p_b(w2),  w1 ~ p_l, w2 ~ p_b,
/// with w_l + w_b = 1 for every direction (balance p_s / (p_l + p_b), power p_s^2 / (..)), so
/// E[Y] = integral of (w_l + w_b) f Le cos = L_r. Each weight is small exactly where its
/// strategy's f Le cos / p is large (p small): Var[Y] stays within a small factor of the
/// better strategy's for every plate and light (Veach's theorem 9.2: with one sample of each,
/// the balance heuristic's variance exceeds that of ANY weighting by at most L_r^2 / 2; the
/// power heuristic trades that bound for lower variance where one pdf dominates).
inline double estimate_mis(const VeachPlates& scene, const Hit& hit, const Vec3& wo,
                           MisHeuristic heuristic, Rng& rng, RayCount& count) {
  // ASSIGNMENT a6.3 BEGIN stub: (void)scene; (void)hit; (void)wo; (void)heuristic; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_mis);
  const GlossySample l = draw_light_sample(scene, hit, wo, rng, count);
  const GlossySample b = draw_bsdf_sample(scene, hit, wo, rng, count);
  return mis_weight(heuristic, l.pdf_light, l.pdf_bsdf) * sample_value(l.f_le_cos, l.pdf_light) +
         mis_weight(heuristic, b.pdf_bsdf, b.pdf_light) * sample_value(b.f_le_cos, b.pdf_bsdf);
  // ASSIGNMENT a6.3 END
}

/// One pixel sample of the figure: the camera ray, then (on a plate) the reflected light by
/// `strategy` at an equal ray count: light or BSDF sampling average TWO samples, MIS takes one
/// of each, so every strategy traces 3 rays (camera + 2) per sample that hits a plate, 1 for a
/// sample that hits a light (its Le, weight 1: no other strategy can see it) or nothing.
inline Color estimate_plates_radiance(const VeachPlates& scene, const Ray& ray,
                                      GlossyStrategy strategy, Rng& rng, RayCount& count) {
  ++count.rays;
  const std::optional<Hit> hit = closest_hit(scene, ray);
  if (!hit) return Color(0.0);
  if (scene.is_light(*hit)) return Color(scene.radiance[scene.light_index(*hit)]);
  const Vec3 wo = -ray.direction;
  double l = 0.0;
  switch (strategy) {
    case GlossyStrategy::light:
      l = 0.5 * (estimate_light_sampling(scene, *hit, wo, rng, count) +
                 estimate_light_sampling(scene, *hit, wo, rng, count));
      break;
    case GlossyStrategy::bsdf:
      l = 0.5 * (estimate_bsdf_sampling(scene, *hit, wo, rng, count) +
                 estimate_bsdf_sampling(scene, *hit, wo, rng, count));
      break;
    case GlossyStrategy::mis_balance:
      l = estimate_mis(scene, *hit, wo, MisHeuristic::balance, rng, count);
      break;
    case GlossyStrategy::mis_power:
      l = estimate_mis(scene, *hit, wo, MisHeuristic::power, rng, count);
      break;
  }
  return Color(l);
}

}  // namespace mcrt
