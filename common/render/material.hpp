#pragma once
/// Materials: a diffuse part, the lecture's first kind, f_r = albedo / pi, and optionally a
/// glossy lobe, the normalised modified Phong lobe of sampling/phong.hpp round the mirror
/// direction; and an emitted radiance Le that is the same in every direction. A material is
/// one side of a surface: a quad may have another on its back (Scene::add_quad), which is how
/// the Cornell lamp emits downwards only.
///
/// The lobe is plain data beside the albedo (no virtual call, no allocation): `specular` = 0
/// means none, and then f_r is albedo / pi exactly, whatever the directions, so a diffuse scene
/// renders the same bits as before the lobe existed.
///
/// A material may instead be a DELTA, perfectly specular: a mirror, or a dielectric (glass)
/// that reflects or refracts by Fresnel and Snell (render/specular.hpp). Its f_r is a Dirac
/// delta: no sampled or light direction ever meets it, so a delta has no diffuse part
/// (albedo 0, f_r = 0 everywhere) and is only ever SAMPLED, never evaluated: the estimators ask
/// is_delta() and follow its one direction. Its `tint` multiplies what it sends on.

#include <cstdint>

#include "core/math.hpp"
#include "sampling/phong.hpp"

namespace mcrt {

/// A perfectly specular surface, or none.
enum class Delta : std::uint8_t { none, mirror, dielectric };

/// Which reflectance a dielectric uses: the exact Fresnel equations, or Schlick's
/// approximation, only to render smallpt's scene as smallpt does (render/fresnel.hpp).
enum class FresnelModel : std::uint8_t { exact, schlick };

struct Material {
  Color albedo{0.0};      ///< diffuse reflectance rho in [0,1]^3
  Color emission{0.0};    ///< emitted radiance Le
  double specular = 0.0;  ///< rho_s of the Phong lobe (grey); 0: no lobe. albedo + rho_s <= 1
  double exponent = 1.0;  ///< the lobe's Phong exponent m in [1, 1e4]: 1 rough, 1e4 nearly a mirror
  Delta delta = Delta::none;  ///< mirror or dielectric: then albedo and the lobe are 0
  Color tint{1.0};   ///< a delta's factor on what it reflects or transmits (smallpt: 0.999)
  double ior = 1.5;  ///< dielectric: refractive index inside over outside (> 0)
  FresnelModel fresnel = FresnelModel::exact;  ///< dielectric: exact, or Schlick's for smallpt

  /// Lambertian BRDF f_r = rho / pi, independent of the directions: the diffuse part alone.
  Color brdf() const { return albedo * k_inv_pi; }
  bool is_emitter() const { return emission != Color(0.0); }
  bool has_lobe() const { return specular > 0.0; }
  bool is_delta() const { return delta != Delta::none; }
  /// The lobe alone, as sampling/phong.hpp's parameters (its rho_d is in albedo).
  Phong lobe() const { return Phong{0.0, specular, exponent}; }

  /// f_r(wi, wo) at a point of unit normal n facing wo (Hit::normal), wi and wo unit and
  /// pointing away from the surface: rho / pi plus the Phong lobe
  /// rho_s (m + 2) / (2 pi) max(0, wi . r(wo))^m, which is 0 for wi below the surface.
  /// Without a lobe it returns brdf() itself.
  Color f_r(const Vec3& wi, const Vec3& wo, const Vec3& n) const {
    if (!has_lobe()) return brdf();
    return brdf() + Color(phong_brdf(lobe(), wi, wo, n));
  }
};

/// f_r cos(theta_i) / p for a cosine-weighted direction wi (p = cos(theta_i) / pi): pi f_r,
/// which for a diffuse material is its albedo, exactly (the cosines cancel).
inline Color cosine_bounce_weight(const Material& material, const Vec3& wi, const Vec3& wo,
                                  const Vec3& n) {
  return material.has_lobe() ? material.f_r(wi, wo, n) * k_pi : material.albedo;
}

}  // namespace mcrt
