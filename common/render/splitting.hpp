#pragma once
/// Splitting, Russian roulette's counterpart: where a path's weight is large, it goes on as n
/// paths, each carrying 1/n of the weight.
///
///   roulette   (small weight)  go on with probability q, weight beta / q
///   splitting  (large weight)  go on n times,             weight beta / n each
///
/// At a splitting vertex x_j, with n independent directions wi_k and their bounce weights
/// w_k = f_r cos(theta_i) / p(wi_k), the estimate is
///
///   L_j = Le(x_j) + (1/n) sum_k w_k L_{j+1,k}
///
/// E[L_j] = Le + E[w L_{j+1}] whatever n: unbiased. The n terms are independent given x_j, so
/// their mean has 1/n of one term's variance; but everything after x_j is traced n times.
///
/// A path's weight is largest where it starts (beta_0 = 1, then about a^j in the furnace), so
/// the fixed policy splits the first s vertices (s = Splitting::depth) and plays roulette after
/// d of them (d = Roulette::min_depth >= s): the counterpart of fixed-q roulette after d.
///
/// Closed forms in the furnace (albedo a, emission Le, uniform hemisphere sampling:
/// E[w] = a, E[w^2] = b = 4 a^2 / 3; m = Le / (1 - a)), fixed q, s <= d. Split at vertices
/// 0..s-1; from vertex s on the path is fixed-q roulette with d - s bounces before it:
///   Var_0 = furnace_roulette_variance(a, Le, d - s, q),  R_0 = (d - s) + 1/(1 - q)  (its rays)
/// and one splitting vertex more (j = 1..s), from Var[w T] = E[w^2] E[T^2] - (E[w] E[T])^2:
///   Var_j = (b (Var_{j-1} + m^2) - a^2 m^2) / n,          R_j = 1 + n R_{j-1}
/// Mean m, variance Var_s, expected rays R_s. At s = 1: Var_1 = V_roulette(d, q) / n and
/// R_1 = 1 + n (d - 1 + 1/(1 - q)): the efficiency 1 / (Var_1 R_1) rises with n towards
/// E[R] / (E[R] - 1) times roulette's, E[R] = d + 1/(1 - q): only the shared camera ray is saved.

#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/render.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/sampling.hpp"

namespace mcrt {

struct Splitting {
  int depth = 1;  ///< s: vertices 0..s-1 split
  int n = 2;      ///< the paths each splitting vertex goes on as
};

/// One bounce from a hit: the direction and its weight f_r cos(theta_i) / p(wi); uniform on
/// the hemisphere, or the one direction of a delta.
struct Bounce {
  Ray ray;
  Color weight{0.0};
};

inline Bounce sample_bounce(const Material& material, const Hit& hit, const Vec3& wo, Rng& rng) {
  if (material.is_delta()) {
    const BsdfSample specular = sample_delta(material, hit, wo, rng.uniform());
    return {spawn_ray(hit, specular.wi), specular.weight};
  }
  const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
  const Vec3 wi = Frame(hit.normal).to_world(local);
  return {spawn_ray(hit, wi),
          material.f_r(wi, wo, hit.normal) * local.z / uniform_hemisphere_pdf()};
}

/// The radiance of the path from `ray`, whose first vertex is vertex `bounce` and whose weight
/// so far is `beta` (included in the result). Vertices before splitting.depth go on as
/// splitting.n paths of weight beta w_k / n each; the others as chapter 06's roulette path.
inline Color trace_split_path(const Scene& scene, Ray ray, Color beta, int bounce,
                              const Roulette& roulette, const Splitting& splitting, Rng& rng,
                              RayCount& count) {
  // ASSIGNMENT a5.1 BEGIN needs=a4.1 withheld stub: (void)scene; (void)ray; (void)beta; (void)bounce; (void)roulette; (void)splitting; (void)rng; (void)count; NOT_IMPLEMENTED(trace_split_path);
  Color radiance(0.0);
  for (;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;
    if (bounce >= roulette.min_depth) {
      const double q = survival_probability(roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }
    const Vec3 wo = -ray.direction;
    if (bounce < splitting.depth) {  // a large weight: n paths, each with 1/n of it
      const Color share = beta / static_cast<double>(splitting.n);
      for (int k = 0; k < splitting.n; ++k) {
        const Bounce next = sample_bounce(material, *hit, wo, rng);
        if (next.weight == Color(0.0)) continue;
        radiance += trace_split_path(scene, next.ray, share * next.weight, bounce + 1, roulette,
                                     splitting, rng, count);
      }
      break;  // the branches carry the rest
    }
    const Bounce next = sample_bounce(material, *hit, wo, rng);
    beta *= next.weight;
    if (beta == Color(0.0)) break;
    ray = next.ray;
  }
  return radiance;
  // ASSIGNMENT a5.1 END
}

/// One estimate of the radiance along `ray` with splitting (the first splitting.depth vertices,
/// n ways each) and roulette (after roulette.min_depth). Unbiased for the whole series.
inline Color estimate_path_radiance_splitting(const Scene& scene, const Ray& ray,
                                              const Roulette& roulette, const Splitting& splitting,
                                              Rng& rng, RayCount& count) {
  return trace_split_path(scene, ray, Color(1.0), 0, roulette, splitting, rng, count);
}

// ---------------------------------------------------------------------------------------------
// Furnace closed forms (derived at the top of this file), fixed q, splitting.depth <= d.

/// Var[L] with splitting: Var_0 = roulette's with d - s, Var_j = (b (Var_{j-1} + m^2) - a^2 m^2) / n.
inline double furnace_splitting_variance(double albedo, double emission, int min_depth, double q,
                                         const Splitting& splitting) {
  const double a = albedo, b = furnace_roulette_variance_threshold(albedo);
  const double m = furnace_radiance_untruncated(albedo, emission);
  double variance = furnace_roulette_variance(albedo, emission, min_depth - splitting.depth, q);
  for (int j = 1; j <= splitting.depth; ++j)
    variance = (b * (variance + m * m) - a * a * m * m) / splitting.n;
  return variance;
}

/// E[rays] with splitting: R_0 = (d - s) + 1/(1 - q), R_j = 1 + n R_{j-1}.
inline double furnace_splitting_mean_rays(int min_depth, double q, const Splitting& splitting) {
  double rays = furnace_roulette_mean_rays(min_depth - splitting.depth, q);
  for (int j = 1; j <= splitting.depth; ++j) rays = 1.0 + splitting.n * rays;
  return rays;
}

}  // namespace mcrt
