#pragma once
/// Multiple importance sampling (MIS): every bounce draws TWO directions towards the light, one
/// by light sampling (p_l) and one by BSDF sampling (p_b, here cosine), and weights each
/// sample's contribution so that the weights of the two strategies sum to 1 for every
/// direction:
///
///   Ld ~ w_l(wl) f_r Le cos / p_l(wl)  +  w_b(wb) f_r Le cos / p_b(wb),
///   w_l(w) + w_b(w) = 1 wherever f_r Le cos > 0   =>   E[Ld] = integral of f_r Le cos dw,
///
/// because E[w_s f / p_s] = integral of w_s f, and the two integrals add to the integral of f.
/// The heuristics (Veach 1997), with n_s = 1 sample per strategy:
///   balance  w_s = p_s / (p_l + p_b)
///   power    w_s = p_s^2 / (p_l^2 + p_b^2)
/// Where one pdf is much larger, its strategy takes (nearly) all the weight: light sampling for
/// small lights, BSDF sampling for large ones. The variance is never much worse than that of
/// the better strategy alone (Veach: balance is within a known bound of the best weights).
///
/// On the path: the BSDF-sampled direction is also the path's next direction, so when it hits
/// a light its Le is added with w_b (and p_l of that direction), and the camera ray's hit adds
/// Le with weight 1 (only one strategy can produce it). Paths end by Russian roulette (chapter
/// 06) and at the depth cut if one is given.
///
/// In the furnace (the whole sphere the light, NEE's exact direct term a Le): both strategies'
/// terms estimate a Le, the light one exactly, so MIS's per-path result has the mean
/// Le (1 + a + ... + a^k) at depth k and a small but non-zero variance (the BSDF-sampled half
/// of the weight is not constant).

#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/light_sampling.hpp"
#include "render/next_event_estimation.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "render/specular.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt {

enum class MisHeuristic { balance, power };

/// The balance heuristic w_s = p_s / (p_s + p_o) for the strategy of pdf p_s against the
/// other's p_o (both per steradian); 0 when both are 0 (a direction neither strategy can draw
/// carries no sample).
inline double balance_heuristic(double p_s, double p_o) {
  // ASSIGNMENT a6.2 BEGIN stub: (void)p_s; (void)p_o; NOT_IMPLEMENTED(balance_heuristic);
  const double sum = p_s + p_o;
  return sum > 0.0 ? p_s / sum : 0.0;
  // ASSIGNMENT a6.2 END
}

/// The power heuristic (exponent 2) w_s = p_s^2 / (p_s^2 + p_o^2); 0 when both are 0.
inline double power_heuristic(double p_s, double p_o) {
  // ASSIGNMENT a6.2 BEGIN stub: (void)p_s; (void)p_o; NOT_IMPLEMENTED(power_heuristic);
  const double p_s2 = p_s * p_s, p_o2 = p_o * p_o;
  const double sum = p_s2 + p_o2;
  return sum > 0.0 ? p_s2 / sum : 0.0;
  // ASSIGNMENT a6.2 END
}

/// w_s by the heuristic named.
inline double mis_weight(MisHeuristic heuristic, double p_s, double p_o) {
  return heuristic == MisHeuristic::power ? power_heuristic(p_s, p_o) : balance_heuristic(p_s, p_o);
}

/// One path's MIS estimate of the radiance arriving along `ray`.
inline Color estimate_mis_radiance(const Scene& scene, Ray ray, const PathEnd& end,
                                   MisHeuristic heuristic, Rng& rng, RayCount& count) {
  // ASSIGNMENT a5.3 BEGIN needs=a5.1,a5.2 withheld stub: (void)scene; (void)ray; (void)end; (void)heuristic; (void)rng; (void)count; NOT_IMPLEMENTED(estimate_mis_radiance);
  Color radiance(0.0);
  Color beta(1.0);        // path weight: product of f_r cos / (p_b q_j) = rho / q_j so far
  double pdf_bsdf = 0.0;  // p_b of the direction that reached this vertex (0: the camera ray,
                          // -1: a delta's, which light sampling cannot draw)
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    if (material.is_emitter()) {  // Le reached by BSDF sampling: weight w_b (1 for the eye)
      // After a delta (pdf_bsdf < 0) light sampling could not have drawn this direction: 1.
      const double w_b = bounce == 0 || pdf_bsdf < 0.0
                             ? 1.0
                             : mis_weight(heuristic, pdf_bsdf, light_pdf_towards(scene, ray, *hit));
      radiance += beta * w_b * material.emission;
    }
    if (end.cut_at(bounce)) break;
    if (bounce >= end.roulette.min_depth) {
      const double q = survival_probability(end.roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }

    const Vec3 wo = -ray.direction;
    if (material.is_delta()) {  // no light sample meets a delta's direction: follow it, w_b = 1
      const BsdfSample specular = sample_delta(material, *hit, wo, rng.uniform());
      pdf_bsdf = -1.0;  // a delta: the next emitter's weight is 1
      beta *= specular.weight;
      if (beta == Color(0.0)) break;
      ray = spawn_ray(*hit, specular.wi);
      continue;
    }

    // Light sampling: f_r Le cos / p_l, weight w_l(p_l, p_b).
    const DirectSample light = sample_direct_light(scene, *hit, rng, count);
    if (light.contributes()) {
      const double w_l = mis_weight(heuristic, light.pdf_light, cosine_hemisphere_pdf(light.cos_x));
      radiance += beta * w_l * material.f_r(light.wi, wo, hit->normal) * light.le * light.cos_x /
                  light.pdf_light;
    }

    // BSDF sampling: the cosine direction, also the path's next direction.
    const Vec3 local = sample_cosine_hemisphere(rng.uniform2());
    pdf_bsdf = cosine_hemisphere_pdf(local.z);
    if (!(pdf_bsdf > 0.0)) break;  // u on the edge of [0,1)^2: probability 2^-32
    const Vec3 wi = Frame(hit->normal).to_world(local);
    beta *= cosine_bounce_weight(material, wi, wo, hit->normal);  // f_r cos / p_b (diffuse: rho)
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, wi);
  }
  return radiance;
  // ASSIGNMENT a5.3 END
}

}  // namespace mcrt
