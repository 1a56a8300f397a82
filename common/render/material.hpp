#pragma once
/// Diffuse materials: the lecture's only kind. f_r = albedo / pi, and an emitted radiance Le
/// that is the same in every direction. A material is one side of a surface: a quad may have
/// another on its back (Scene::add_quad), which is how the Cornell lamp emits downwards only.

#include "core/math.hpp"

namespace mcrt {

struct Material {
  Color albedo{0.0};    ///< reflectance rho in [0,1]^3
  Color emission{0.0};  ///< emitted radiance Le

  /// Lambertian BRDF f_r(wi, wo) = rho / pi, independent of the directions.
  Color brdf() const { return albedo * k_inv_pi; }
  bool is_emitter() const { return emission != Color(0.0); }
};

}  // namespace mcrt
