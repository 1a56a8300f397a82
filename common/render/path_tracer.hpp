#pragma once
/// The simplest path tracer: the rendering equation with one sampled direction per bounce.
///
///   L(x, wo) = Le(x) + integral over the hemisphere of f_r L(x', -wi) cos(theta_i) dwi
///
/// Following one direction wi ~ p per bounce turns the recursion into a loop that carries the
/// path weight beta = product of f_r cos(theta_i) / p(wi) over the bounces so far:
///
///   L ~ sum over bounces j = 0..k of beta_j Le(x_j),   beta_0 = 1,
///
/// an unbiased estimate of the radiance of paths with at most k bounces (k = max_depth).
/// Here p = 1/(2 pi) (uniform on the hemisphere); on a diffuse surface f_r = rho/pi, so
/// beta_{j+1} = beta_j 2 rho cos(theta_i) (Material::f_r adds a glossy lobe where there is one).
///
/// Expectation and variance in the furnace (albedo a, emission Le everywhere): with c_j the
/// cosines, uniform on [0,1], beta_j = prod (2 a c_i) has E[beta_j] = a^j and
/// E[beta_j^2] = b^j with b = 4 a^2 / 3, so
///   E[L]   = Le (1 + a + ... + a^k) = Le (1 - a^(k+1)) / (1 - a),
///   E[L^2] = Le^2 sum over i, j of E[beta_i beta_j] = Le^2 sum_j b^j (1 + 2 sum_{l=1..k-j} a^l),
///   Var[L] = E[L^2] - E[L]^2   (furnace_radiance_variance below).

#include <algorithm>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/sampling.hpp"

namespace mcrt {

/// One path's estimate of the radiance arriving along `ray`, with at most `max_depth` bounces
/// (max_depth + 1 closest-hit queries, each counted in `count`). `rng` is where the uniforms
/// come from: an Rng stream, or a PaddedSample (sampling/path_sampler.hpp, --sampler) whose
/// uniform2() is the next 2D set's point; each bounce asks for one 2D point (or one uniform).
template <class Uniforms = Rng>
inline Color estimate_path_radiance(const Scene& scene, Ray ray, int max_depth, Uniforms& rng,
                                    RayCount& count) {
  // ASSIGNMENT a4.1 BEGIN needs=a2.1 stub: (void)scene; (void)ray; (void)max_depth; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_path_radiance);
  Color radiance(0.0);
  Color beta(1.0);  // path weight: product of f_r cos(theta_i) / pdf(wi) so far
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;  // the path leaves the scene: nothing more is emitted towards it
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;  // Le(x_j), weighted by the path so far
    if (bounce == max_depth) break;

    const Vec3 wo = -ray.direction;  // towards where the path came from
    if (material.is_delta()) {       // a mirror or glass: follow the one direction it sends light
      const BsdfSample specular = sample_delta(material, *hit, wo, rng.uniform());
      beta *= specular.weight;  // f_r cos / p of a delta: the tint
      if (beta == Color(0.0)) break;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }
    // Uniform sampling alone would never find a delta's one direction: a mirror stays black.
    const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
    const Vec3 wi = Frame(hit->normal).to_world(local);
    const double cos_theta_i = local.z;  // the normal is the frame's z axis
    beta *= material.f_r(wi, wo, hit->normal) * cos_theta_i / uniform_hemisphere_pdf();
    // A black surface ends the path exactly: every later term would be multiplied by 0.
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
  // ASSIGNMENT a4.1 END
}

/// E[L] in the furnace after at most k bounces: Le (1 + a + ... + a^k).
inline double furnace_radiance(double albedo, double emission, int max_depth) {
  double sum = 0.0, a_j = 1.0;
  for (int j = 0; j <= max_depth; ++j, a_j *= albedo) sum += a_j;
  return emission * sum;
}

/// Var[L] in the furnace for any direction pdf whose bounce weight w has E[w] = a and
/// E[w^2] = b (independent bounces): E[L^2] = Le^2 sum_j b^j (1 + 2 sum_{l=1..k-j} a^l).
inline double furnace_radiance_variance_from_moments(double albedo, double b, double emission,
                                                     int max_depth) {
  double second_moment = 0.0, b_j = 1.0;
  for (int j = 0; j <= max_depth; ++j, b_j *= b) {
    double tail = 0.0, a_l = albedo;  // sum_{l=1..k-j} a^l
    for (int l = 1; l <= max_depth - j; ++l, a_l *= albedo) tail += a_l;
    second_moment += b_j * (1.0 + 2.0 * tail);
  }
  const double mean = furnace_radiance(albedo, 1.0, max_depth);
  return emission * emission * std::max(0.0, second_moment - mean * mean);
}

/// Var[L] in the furnace for uniform hemisphere sampling (see the top of this file):
/// b = E[(2 a cos)^2] = 4 a^2 / 3.
inline double furnace_radiance_variance(double albedo, double emission, int max_depth) {
  return furnace_radiance_variance_from_moments(albedo, 4.0 * albedo * albedo / 3.0, emission,
                                                max_depth);
}

}  // namespace mcrt
