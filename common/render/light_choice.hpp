#pragma once
/// Choosing which light to sample: uniformly, P_j = 1/N, or by power, P_j = Phi_j / sum_i Phi_i,
/// on a scene made to show the difference: a diffuse floor lit by two sphere lights, one bright
/// and high, one dim (1/100 of the power) and low beside the floor's corner.
///
/// The direct light leaving a floor point x (albedo rho, f_r = rho / pi), one sample: pick
/// light j with probability P_j, a direction w uniform in the cone it subtends from x
/// (p_j(w) = 1 / (2 pi (1 - cos alpha_j)), sin alpha_j = r_j / d_j), and
///
///   Y = f_r Le_j cos(theta_w) / (P_j p_j(w)),
///   E[Y] = sum_j P_j integral over cone_j of f_r Le_j cos / (P_j p_j) p_j dw = L_r
///
/// for every choice with P_j > 0 for each light that lights x. Where a sphere is wholly above
/// x's horizon, integral over its cone of cos dw = pi sin^2(alpha) cos(theta_c) (theta_c the
/// angle of its centre), so
///
///   L_r(x) = rho sum_j Le_j (r_j / d_j)^2 cos(theta_c,j).
///
/// Which choice is better: with C_j light j's share of L_r and the small spread of cos inside
/// a cone left out, Var Y = sum_j C_j^2 / P_j - L_r^2, zero for P_j = C_j / L_r. Uniform choice
/// gives (C_0 - C_1)^2 for two lights: about L_r^2 wherever one light dominates. Power choice is
/// C_j-proportional where both lights are about as far (C_j ~ Phi_j cos / d_j^2), so almost
/// noiseless far from the dim light, and far off beside it, where C_1 ~ C_0 but P_1 = 1/101.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "geometry/ray.hpp"
#include "geometry/sphere.hpp"
#include "sampling/light.hpp"

namespace mcrt {

/// How a light is picked.
enum class LightChoice { uniform, power };

/// The floor and its two lights. The floor is the patch [-2, 2] x [-1, 1] of the plane y = 0
/// (normal +y). The bright light hangs over the patch; the dim one sits low beyond its z = 1
/// edge, beside the corner x = 1: every segment between the patch and the bright light keeps
/// z <= 1 and height >= 0, every one to the dim light height <= 0.4, so neither light shadows
/// the other and both are wholly above every patch point's horizon (the closed form holds).
struct TwoLights {
  std::array<Sphere, 2> lights{Sphere{{-1.0, 3.0, 0.0}, 0.5, 0}, Sphere{{1.0, 0.3, 1.3}, 0.1, 1}};
  std::array<double, 2> power{400.0, 4.0};  ///< Phi_j: the bright one 100 times the dim one
  double albedo = 0.5;                      ///< rho of the floor
  double half_x = 2.0, half_z = 1.0;        ///< the patch's half sides

  /// Le_j = Phi_j / (4 pi^2 r_j^2) (a sphere of radius r and radiance Le emits 4 pi^2 r^2 Le).
  double radiance(std::size_t j) const {
    return power[j] / (4.0 * k_pi * k_pi * lights[j].radius * lights[j].radius);
  }
  /// The patch point under the pixel (px, py) of a width x height map of it seen from above.
  Vec3 floor_point(double px, double py, int width, int height) const {
    return {(px / width - 0.5) * 2.0 * half_x, 0.0, (py / height - 0.5) * 2.0 * half_z};
  }
};

/// P_j: 1/N for uniform choice, Phi_j / sum_i Phi_i by power.
inline double light_choice_probability(const TwoLights& scene, LightChoice choice, std::size_t j) {
  if (choice == LightChoice::uniform) return 1.0 / static_cast<double>(scene.lights.size());
  double total = 0.0;
  for (double phi : scene.power) total += phi;
  return scene.power[j] / total;
}

/// The light that u in [0, 1) picks: the first j whose cumulative P exceeds u.
inline std::size_t pick_light(const TwoLights& scene, LightChoice choice, double u) {
  double cumulative = 0.0;
  for (std::size_t j = 0; j + 1 < scene.lights.size(); ++j) {
    cumulative += light_choice_probability(scene, choice, j);
    if (u < cumulative) return j;
  }
  return scene.lights.size() - 1;
}

/// Light j's term of the closed form at the floor point x: rho Le_j (r_j / d_j)^2 cos(theta_c).
inline double light_share(const TwoLights& scene, std::size_t j, const Vec3& x) {
  const Vec3 to_centre = scene.lights[j].center - x;
  const double d2 = glm::dot(to_centre, to_centre);
  const double cos_c = to_centre.y / std::sqrt(d2);
  return scene.albedo * scene.radiance(j) * scene.lights[j].radius * scene.lights[j].radius / d2 *
         cos_c;
}

/// L_r(x), the closed form (see the top of this file).
inline double exact_floor_radiance(const TwoLights& scene, const Vec3& x) {
  return light_share(scene, 0, x) + light_share(scene, 1, x);
}

/// One sample of Y at the floor point x: a light by `choice`, a direction in its cone, and the
/// shadow ray along it (counted in `count`; the layout never blocks it, but it is traced).
inline double estimate_floor_radiance(const TwoLights& scene, const Vec3& x, LightChoice choice,
                                      Rng& rng, RayCount& count) {
  const std::size_t j = pick_light(scene, choice, rng.uniform());
  const Vec3 centre = scene.lights[j].center;
  const double radius = scene.lights[j].radius;
  const LightPoint y = sample_sphere_cone(centre, radius, x, rng.uniform2());
  const Ray shadow(x, glm::normalize(y.point - x));
  ++count.rays;
  const Sphere& other = scene.lights[1 - j];
  const double distance = glm::length(y.point - x);
  if (intersect_distance(other, shadow, {0.0, distance})) return 0.0;
  const double cos_theta = std::max(0.0, shadow.direction.y);
  const double f_r = scene.albedo / k_pi;
  const double p_j = light_choice_probability(scene, choice, j);
  return f_r * scene.radiance(j) * cos_theta /
         (p_j * sphere_cone_pdf_solid_angle(centre, radius, x));
}

}  // namespace mcrt
