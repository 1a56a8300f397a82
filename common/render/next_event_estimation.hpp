#pragma once
/// Next-event estimation (NEE): at every bounce, aim one shadow ray at a light.
///
/// The radiance leaving x_j splits into emitted, direct and indirect light:
///
///   L(x_j, wo) = Le(x_j) + Ld(x_j, wo) + integral of f_r L_indirect(x_j, wi) cos(theta_i) dwi,
///
/// with Ld estimated by a point on a light (render/light_sampling.hpp) and the indirect part by
/// one cosine-weighted direction (f_r cos / p = rho). Along one path, beta_j the path weight
/// (beta_0 = 1, beta_{j+1} = beta_j rho / q_j with Russian roulette as in chapter 06):
///
///   L ~ Le(x_0) + sum over vertices j of beta_j f_r Le(y_j) V cos(theta_x) / p_w(y_j).
///
/// Emission is counted exactly once: the camera ray's hit adds its Le (no light sample can
/// reach the eye), and after that every emitter is reached by light sampling only; a
/// BSDF-sampled ray that happens to hit a light adds nothing (its light is the next vertex's
/// direct term, already counted by the shadow ray one vertex earlier).
///
/// Deltas (mirror, glass): no light sample can land on the one direction a delta sends the
/// path, so at a delta vertex no shadow ray is traced, and the Le that the path meets right
/// after it is counted in full: it is the only strategy that reaches that light. Caustics (light
/// through glass onto a diffuse surface) are reached only that way, by a diffuse bounce that
/// happens to hit the glass and then the light, hence their noise.
///
/// Expectation: the light sample is unbiased for Ld wherever p_A > 0 on every visible light
/// point, and the indirect part is chapter 07's cosine estimator, so E[L] is chapter 05's
/// E[L] (for the same depth cut, or the whole series without one).
///
/// In the furnace (albedo a, emission Le everywhere, unit sphere) the whole sphere is the
/// light. From a point x on its inside, every y on the sphere has cos(theta_x) = cos(theta_y)
/// = r / 2 (chords of a sphere), so cos cos / r^2 = 1/4 and f_r Le cos cos / (r^2 p_A) =
/// (a / pi) Le (1/4) 4 pi = a Le: the direct term is exact, every sample. With the cosine
/// bounce (weight exactly a) and no roulette, each path returns exactly
///   Le (1 + a + ... + a^k)   at depth k (furnace_radiance):   Var[L] = 0.
/// With roulette the mean is Le / (1 - a) and the variance is roulette's alone.

#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/light_sampling.hpp"
#include "render/render.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt {

/// How a path ends: by Russian roulette, and also at a depth cut if max_depth >= 0 (bounces
/// after the camera ray's hit, as chapter 05's --depth).
struct PathEnd {
  Roulette roulette;
  int max_depth = -1;  ///< < 0: no cut

  bool cut_at(int bounce) const { return max_depth >= 0 && bounce >= max_depth; }
};

/// One path's NEE estimate of the radiance arriving along `ray`.
inline Color estimate_nee_radiance(const Scene& scene, Ray ray, const PathEnd& end, Rng& rng,
                                   RayCount& count) {
  // ASSIGNMENT a5.3 BEGIN needs=a4.1,a2.2 stub: (void)scene; (void)ray; (void)end; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_nee_radiance);
  Color radiance(0.0);
  Color beta(1.0);           // path weight: product of f_r cos / (p q_j) = rho / q_j so far
  bool after_delta = false;  // the ray left a mirror or glass: no light sample could aim along it
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    // Le seen by the eye, or through mirrors and glass from it: counted here only (beta = 1
    // at the eye).
    if (bounce == 0 || after_delta) radiance += beta * material.emission;
    if (end.cut_at(bounce)) break;
    if (bounce >= end.roulette.min_depth) {
      const double q = survival_probability(end.roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }

    const Vec3 wo = -ray.direction;
    after_delta = material.is_delta();
    if (after_delta) {  // a light sample cannot meet a delta's direction: follow it instead
      const BsdfSample specular = sample_delta(material, *hit, wo, rng.uniform());
      beta *= specular.weight;
      if (beta == Color(0.0)) break;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }

    // Direct light: f_r Le cos(theta_x) / p_w(wi), if the shadow ray reaches the light.
    const DirectSample light = sample_direct_light(scene, *hit, rng, count);
    if (light.contributes())
      radiance +=
          beta * material.f_r(light.wi, wo, hit->normal) * light.le * light.cos_x / light.pdf_light;

    // Indirect light: one cosine-weighted direction, f_r cos / p (= rho on a diffuse surface).
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    if (!(local.z > 0.0)) break;  // u on the edge of [0,1)^2: density 0, probability 2^-32
    const Vec3 wi = Frame(hit->normal).to_world(local);
    beta *= cosine_bounce_weight(material, wi, wo, hit->normal);
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
  // ASSIGNMENT a5.3 END
}

/// The baseline NEE is measured against: BSDF (cosine) sampling alone with the same path end,
/// Le added at every vertex as in chapters 05-07 (chapter 07's estimator with chapter 06's
/// roulette). Its E[L] is NEE's.
inline Color estimate_cosine_roulette_radiance(const Scene& scene, Ray ray, const PathEnd& end,
                                               Rng& rng, RayCount& count) {
  // ASSIGNMENT a5.1 BEGIN needs=a5.2 withheld stub: (void)scene; (void)ray; (void)end; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_cosine_roulette_radiance);
  Color radiance(0.0);
  Color beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;
    if (end.cut_at(bounce)) break;
    if (bounce >= end.roulette.min_depth) {
      const double q = survival_probability(end.roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }
    if (material.is_delta()) {  // a mirror or glass: its one direction
      const BsdfSample specular = sample_delta(material, *hit, -ray.direction, rng.uniform());
      beta *= specular.weight;
      if (beta == Color(0.0)) break;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    if (!(local.z > 0.0)) break;
    const Vec3 wi = Frame(hit->normal).to_world(local);
    beta *= cosine_bounce_weight(material, wi, -ray.direction, hit->normal);
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
  // ASSIGNMENT a5.1 END
}

}  // namespace mcrt
