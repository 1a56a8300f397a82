#pragma once
// The two laws of plain ray tracing's shading, checked on the run's own scene.
//
// Straight below the lamp, on a surface facing it at depth h, the direct light is
//   L(0) = f_r I(0) / h^2 = (rho / pi) Le A / h^2          (the inverse-square law).
// At an angle theta off the lamp's normal, on the same plane, the distance is r = h / cos(theta),
// the lamp sends I(theta) = I(0) cos(theta) and the surface receives it at cos(theta), so
//   L(theta) = (rho / pi) I(0) cos(theta) cos(theta) / r^2 = L(0) cos^4(theta)  (the cos^4 law).
// measure_falloff shades the points the lamp sees at theta = 0, 2.5, ..., 70 degrees, in four
// directions about its normal, with the chapter's own shade() and compares each with that
// closed form; points off that plane (a wall, a box in the way) are left out.

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/math.hpp"
#include "render/scene.hpp"

namespace mcrt {

struct Falloff {
  double height = 0.0;             ///< h: from the lamp to the surface straight below it
  double predicted_below = 0.0;    ///< (rho / pi) Le A / h^2, the mean of its three colours
  double measured_below = 0.0;     ///< shade() at that point, the mean of its three colours
  int points = 0;                  ///< the angles whose point lies on that plane (theta = 0 too)
  double largest_angle = 0.0;      ///< in degrees, of those points
  double largest_deviation = 0.0;  ///< max over points and colours of |L / L_predicted - 1|
};

/// The falloff below the scene's point light, or nothing if it has none or nothing faces it
/// straight below. `shade(scene, hit, count)` is the chapter's shading.
template <class Shade>
std::optional<Falloff> measure_falloff(const Scene& scene, Shade shade) {
  const PointLight& light = scene.point_light;
  const Vec3 down = light.normal;  // the lamp's normal points at the floor
  if (light.intensity == Color(0.0) || glm::length(down) == 0.0) return std::nullopt;
  const Vec3 u =
      glm::normalize(glm::cross(down, std::abs(down.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  const Vec3 v = glm::cross(down, u);
  std::optional<Falloff> falloff;
  for (int step = 0; step <= 28; ++step) {  // theta = step x 2.5 degrees
    for (const Vec3& across : {u, -u, v, -v}) {
      if (step == 0 && across != u) break;  // theta = 0 is one point
      const double degrees = 2.5 * step, theta = degrees * k_pi / 180.0;
      const Ray ray(light.position, std::cos(theta) * down + std::sin(theta) * across);
      const std::optional<Hit> hit = scene.closest_hit(ray);
      if (!hit) continue;
      const double depth = glm::dot(hit->point - light.position, down);
      if (!falloff) {  // theta = 0: the plane straight below, which must face the lamp
        if (step != 0 || glm::dot(hit->normal, down) > -1.0 + 1e-12) return std::nullopt;
        falloff = Falloff{depth};
      }
      // Only points of that plane: the same depth, facing the lamp.
      if (std::abs(depth - falloff->height) > 1e-9 * falloff->height ||
          glm::dot(hit->normal, down) > -1.0 + 1e-12)
        continue;
      const Material& material = scene.material(*hit);
      const double c = std::cos(theta);
      const Color predicted =
          material.brdf() * light.intensity * (c * c * c * c) / (falloff->height * falloff->height);
      RayCount count;
      const Color measured = shade(scene, *hit, count) - material.emission;
      for (int k = 0; k < 3; ++k)
        falloff->largest_deviation =
            std::max(falloff->largest_deviation, std::abs(measured[k] / predicted[k] - 1.0));
      if (step == 0) {
        falloff->predicted_below = (predicted.r + predicted.g + predicted.b) / 3.0;
        falloff->measured_below = (measured.r + measured.g + measured.b) / 3.0;
      }
      ++falloff->points;
      falloff->largest_angle = degrees;
    }
  }
  return falloff;
}

}  // namespace mcrt
