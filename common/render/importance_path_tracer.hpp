#pragma once
/// Chapter 05's path tracer with the bounce direction drawn from a chosen pdf p: importance
/// sampling. The loop is the same; only the sampler and the pdf in the weight change:
///
///   L ~ sum over bounces j = 0..k of beta_j Le(x_j),   beta_{j+1} = beta_j f_r cos(theta_i) / p(wi)
///
/// Expectation: for any p that is > 0 wherever f_r L cos(theta) > 0,
///   E[f_r L cos / p] = integral of (f_r L cos / p) p dw = integral of f_r L cos dw,
/// so every pdf gives the same E[L] as chapter 05; only the variance changes.
///
/// In the furnace (albedo a, emission Le everywhere; f_r = a / pi) each bounce multiplies the
/// weight by an independent w = a cos(theta) / (pi p), with E[w] = a for every pdf and
///   b = E[w^2] = integral of (a cos / pi)^2 / p dw:
///     uniform (m = 0)   4 a^2 / 3
///     cos^m             4 a^2 / ((m + 1)(3 - m)) for m < 3, INFINITE for m >= 3 (p vanishes
///                       at the horizon faster than the cosine: w ~ cos^(1 - m) explodes there)
///     cosine (m = 1)    a^2 = E[w]^2: w = a exactly, zero variance
///     grazing           pi^2 a^2 / 4
/// Then, as for chapter 05 (beta_j = product of j independent w's, E[beta_i beta_j] =
/// b^i a^(j - i) for i <= j):
///   E[L]   = Le (1 + a + ... + a^k) = Le (1 - a^(k+1)) / (1 - a)        (furnace_radiance)
///   Var[L] = Le^2 ( sum_j b^j (1 + 2 sum_{l=1..k-j} a^l) - (1 + a + ... + a^k)^2 ).
/// With the cosine pdf b = a^2, the two sums are equal and Var[L] = 0: every path returns
/// exactly Le (1 + a + ... + a^k).

#include <cmath>
#include <limits>
#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/cosine_power.hpp"
#include "sampling/frame.hpp"

namespace mcrt {

/// One path's estimate of the radiance arriving along `ray`, with at most `max_depth` bounces,
/// each direction drawn from `pdf`. With the uniform pdf it is estimate_path_radiance, bit for
/// bit.
inline Color estimate_importance_path_radiance(const Scene& scene, Ray ray, int max_depth,
                                               const HemispherePdf& pdf, Rng& rng,
                                               RayCount& count) {
  // ASSIGNMENT a5.2 BEGIN needs=a4.1,a2.2 stub: (void)scene; (void)ray; (void)max_depth; (void)pdf; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_importance_path_radiance);
  Color radiance(0.0);
  Color beta(1.0);  // path weight: product of f_r cos(theta_i) / p(wi) so far
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;
    if (bounce == max_depth) break;

    const Vec3 wo = -ray.direction;  // towards where the path came from
    if (material.is_delta()) {       // a mirror or glass: follow the one direction it sends light
      const BsdfSample specular = sample_delta(material, *hit, wo, rng.uniform());
      beta *= specular.weight;  // f_r cos / p of a delta: the tint
      if (beta == Color(0.0)) break;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }
    const Vec3 local = sample_hemisphere(pdf, rng.uniform2());
    const double cos_theta_i = local.z;
    const double p_wi = hemisphere_pdf(pdf, cos_theta_i);
    // A direction of density 0 comes only from u on the edge of [0,1)^2 (u0 = 0 for cos^m and
    // grazing): probability 2^-32 per bounce. It ends the path instead of dividing by 0.
    if (!(p_wi > 0.0)) break;
    const Vec3 wi = Frame(hit->normal).to_world(local);
    beta *= material.f_r(wi, wo, hit->normal) * cos_theta_i / p_wi;
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
  // ASSIGNMENT a5.2 END
}

/// b = E[w^2] of one furnace bounce's weight w = a cos / (pi p) (table at the top of this file);
/// +infinity for cos^m with m >= 3.
inline double furnace_bounce_second_moment(const HemispherePdf& pdf, double albedo) {
  const double a2 = albedo * albedo;
  if (a2 == 0.0) return 0.0;
  switch (pdf.kind) {
    case HemispherePdf::uniform: return 4.0 * a2 / 3.0;
    case HemispherePdf::cosine: return a2;
    case HemispherePdf::cosine_power:
      return pdf.m < 3 ? 4.0 * a2 / ((pdf.m + 1.0) * (3.0 - pdf.m))
                       : std::numeric_limits<double>::infinity();
    case HemispherePdf::grazing: return k_pi * k_pi * a2 / 4.0;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

/// Var[L] in the furnace with directions drawn from `pdf` (top of this file); 0 for the cosine
/// pdf (to round-off, which the max clamps), +infinity when b is.
inline double furnace_radiance_variance(const HemispherePdf& pdf, double albedo, double emission,
                                        int max_depth) {
  if (max_depth == 0 || emission == 0.0) return 0.0;
  const double b = furnace_bounce_second_moment(pdf, albedo);
  if (std::isinf(b)) return b;
  return furnace_radiance_variance_from_moments(albedo, b, emission, max_depth);
}

}  // namespace mcrt
