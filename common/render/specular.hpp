#pragma once
/// Sampling the delta materials: a perfect mirror and a smooth dielectric (glass).
///
/// A delta BSDF sends the light arriving from wo into one direction (mirror) or one of two
/// (dielectric: the mirror direction or the refracted one); its f_r is a Dirac delta, so its
/// pdf is one too, and the ratio f_r cos / p that a path's weight needs is a plain number:
///
///   mirror      wi = reflect(wo, n),                 weight = tint
///   dielectric  with probability R: wi = reflect,    weight = tint R / R       = tint
///               with probability T: wi = refracted,  weight = tint (1 - R) / T = tint
///               (R the Fresnel reflectance, T = 1 - R; under total internal reflection R = 1)
///
/// so no estimator evaluates a delta's pdf, and with tint 1 every weight is exactly 1: a
/// mirror or a glass ball in a uniform environment is invisible (tests/render/specular_test).
///
/// Radiance crossing into a medium of index eta_t is multiplied by (eta_t / eta_i)^2; a path
/// that enters the glass and leaves it again gets the factor and its inverse. Here paths start
/// at the camera and end at lights in air, so the factors are left out (as smallpt does):
/// the estimate is the same wherever no light or camera sits inside the glass.

#include <algorithm>
#include <optional>

#include "core/math.hpp"
#include "geometry/hit.hpp"
#include "render/fresnel.hpp"
#include "render/material.hpp"

namespace mcrt {

/// A sampled direction with f_r cos / p: for a delta the tint (the Fresnel choice cancels R).
struct BsdfSample {
  Vec3 wi;                   ///< unit, away from the surface
  Color weight{0.0};         ///< f_r cos(theta_i) / p(wi), the delta's ratio of deltas
  bool is_delta = true;      ///< the pdf is a Dirac delta: never to be evaluated or MIS-weighted
  bool transmitted = false;  ///< wi went through the surface (dielectric refraction)
};

/// The mirror: wi = 2 (wo.n) n - wo, weight the tint.
///
/// The directions are normalised once more: a hit point is on its sphere only to round-off, so
/// its normal's length is 1 only to round-off, and reflect() multiplies that error into the
/// direction's length. Inside glass, where a path may reflect thousands of times, an
/// unnormalised direction's error grows about fourfold per bounce (the next hit, computed
/// for a unit direction, lands off the sphere) until the path never leaves.
inline BsdfSample sample_mirror(const Material& material, const Vec3& wo, const Vec3& n) {
  return {glm::normalize(reflect(wo, n)), material.tint, true, false};
}

/// The probability that the dielectric reflects light arriving at cos(theta_i) from the side
/// of index eta_i (cos_t its refracted cosine): the material's Fresnel model. Schlick's takes
/// the cosine on the less dense side, as smallpt does.
inline double dielectric_reflectance(const Material& material, double cos_i, double cos_t,
                                     double eta_i, double eta_t) {
  if (material.fresnel == FresnelModel::schlick)
    return fresnel_schlick(eta_i <= eta_t ? cos_i : cos_t, eta_i, eta_t);
  if (cos_i == 0.0) return 1.0;  // grazing: reflected whole (the exact formula is 0/0 there)
  return fresnel_dielectric(cos_i, cos_t, eta_i, eta_t);
}

/// The dielectric: the path at a hit with unit normal n facing wo, `entering` when wo is on
/// the outside (Hit::front_face), reflects with probability R and refracts otherwise; u in
/// [0, 1) chooses. Outside is air (index 1), inside material.ior.
///
/// The contract (task a6.4): wi is a unit vector, either the mirror direction of wo or the
/// direction Snell's law gives on the far side (transmitted = true); it is the mirror
/// direction with probability R = dielectric_reflectance(...) for light arriving from the
/// side wo is on (indices in that order), and always where no refracted direction exists;
/// weight is the tint, is_delta true. Nothing in it may be NaN.
inline BsdfSample sample_dielectric(const Material& material, const Vec3& wo, const Vec3& n,
                                    bool entering, double u) {
  // ASSIGNMENT a6.4 BEGIN stub: (void)material; (void)wo; (void)n; (void)entering; (void)u; NOT_IMPLEMENTED(sample_dielectric);
  const double eta_i = entering ? 1.0 : material.ior, eta_t = entering ? material.ior : 1.0;
  const double eta = eta_i / eta_t;
  const double cos_i = std::clamp(glm::dot(wo, n), 0.0, 1.0);
  const std::optional<double> cos_t = refracted_cosine(cos_i, eta);
  if (!cos_t) return sample_mirror(material, wo, n);  // total internal reflection: R = 1
  const double reflectance = dielectric_reflectance(material, cos_i, *cos_t, eta_i, eta_t);
  if (u < reflectance) return sample_mirror(material, wo, n);
  return {glm::normalize(refract(wo, n, cos_i, *cos_t, eta)), material.tint, true, true};
  // ASSIGNMENT a6.4 END
}

/// A delta material's sample at `hit`, wo = -(the arriving ray's direction); u in [0, 1) is
/// used by the dielectric only.
inline BsdfSample sample_delta(const Material& material, const Hit& hit, const Vec3& wo, double u) {
  if (material.delta == Delta::mirror) return sample_mirror(material, wo, hit.normal);
  return sample_dielectric(material, wo, hit.normal, hit.front_face, u);
}

}  // namespace mcrt
