#pragma once
/// Veach's plates (thesis fig. 9.2) as plain data: four glossy plates from rough (bottom, near)
/// to sharp (top, far), four sphere lights in a row behind them from small and bright to large
/// and dim, all of the same power, and a camera that sees each light reflected in each plate.
/// Direct light only: render/glossy_direct.hpp estimates what a plate reflects towards the eye.
///
/// The layout. The eye is at (0, 5, 12), the lights on a row at height 5, z = -5, at x = -3,
/// -1, 1, 3. The plates climb away from the eye (centres 0.3 up and 1.6 back each), each a
/// 6 x 1.4 strip tilted about the x axis so that its normal is the half vector between the
/// directions from its centre to the eye and to the middle of the light row: a mirror plate
/// would show the row's centre at its own centre, and every light on the plate's midline
/// (the reflection keeps x, so each light's highlight lies between the eye's x and its own).
/// The steps are shallow and the lights high so that the ray from a highlight to its light
/// passes over the plates behind, and the eye sees each highlight on its own plate
/// (tests/render/glossy_direct_test.cpp checks both).
///
/// Equal power: a sphere of radius r and radiance Le emits Phi = 4 pi^2 r^2 Le, so
/// Le = k_plates_light_power / (4 pi^2 r^2) gives each the same Phi.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/math.hpp"
#include "geometry/camera.hpp"
#include "geometry/hit.hpp"
#include "geometry/quad.hpp"
#include "geometry/sphere.hpp"
#include "render/image.hpp"
#include "sampling/phong.hpp"

namespace mcrt {

/// Phong exponents of the plates, rough to sharp: from a lobe ~0.3 rad wide (1/sqrt(m)), wider
/// than the largest light seen from a plate (radius ~0.09 rad), to ~0.01 rad, wider than the
/// smallest (~0.003 rad) but narrower than the rest: the crossover Veach's figure shows sits
/// inside the range.
inline constexpr std::array<double, 4> k_plate_exponents{10.0, 100.0, 1000.0, 10000.0};
/// Radii of the lights, small to large.
inline constexpr std::array<double, 4> k_plate_light_radii{0.03, 0.1, 0.3, 0.9};
/// The power of each light, Phi = 4 pi^2 r^2 Le: chosen so that the largest light has Le ~ 1
/// and the sharpest plate's reflection of it is not clipped white.
inline constexpr double k_plates_light_power = 30.0;
/// rho_s of every plate: a bright lobe, well below 1 (no material reflects all).
inline constexpr double k_plate_rho_s = 0.8;

/// The scene: plates (quads) with their materials, lights (spheres) with their radiance.
/// Hit::material is the plate's index for a plate and plates.size() + j for light j.
struct VeachPlates {
  std::vector<Quad> plates;
  std::vector<Phong> materials;  ///< one per plate
  std::vector<Sphere> lights;
  std::vector<double> radiance;  ///< Le of each light (grey)
  CameraSpec camera;

  std::size_t plate_count() const { return plates.size(); }
  std::size_t light_count() const { return lights.size(); }
  bool is_light(const Hit& hit) const { return hit.material >= plates.size(); }
  std::size_t light_index(const Hit& hit) const { return hit.material - plates.size(); }
};

/// Le = Phi / (4 pi^2 r^2): the radiance of a sphere of radius r emitting power Phi.
inline double equal_power_radiance(double power, double radius) {
  return power / (4.0 * k_pi * k_pi * radius * radius);
}

/// A plate: the width x depth strip centred at `centre` with unit normal n (normal to the x
/// axis), its edges along x and along n x (x axis).
inline Quad plate_facing(const Vec3& centre, const Vec3& n, double width, double depth,
                         std::uint32_t material) {
  const Vec3 edge_u{width, 0.0, 0.0};
  const Vec3 edge_v = depth * glm::normalize(glm::cross(n, Vec3{1.0, 0.0, 0.0}));
  return Quad(centre - 0.5 * edge_u - 0.5 * edge_v, edge_u, edge_v, material);
}

/// The figure's scene (see the top of this file).
inline VeachPlates make_veach_plates() {
  VeachPlates scene;
  const Vec3 eye{0.0, 5.0, 12.0};
  const Vec3 light_row{0.0, 5.0, -5.0};
  scene.camera.eye = eye;
  // Looking 16 degrees down: the plates (36 to 19 degrees below the eye's horizon) and the
  // lights (on it, the largest 3 degrees in radius) fill the 43-degree field of view.
  scene.camera.direction = Vec3{0.0, -std::tan(0.28), -1.0};
  scene.camera.vertical_fov = 0.75;
  const std::size_t n = k_plate_exponents.size();
  for (std::size_t k = 0; k < n; ++k) {
    const double step = static_cast<double>(k);
    const Vec3 centre{0.0, -1.0 + 0.3 * step, 3.0 - 1.6 * step};
    const Vec3 normal =
        glm::normalize(glm::normalize(eye - centre) + glm::normalize(light_row - centre));
    scene.plates.push_back(plate_facing(centre, normal, 6.0, 1.4, static_cast<std::uint32_t>(k)));
    scene.materials.push_back(Phong{0.0, k_plate_rho_s, k_plate_exponents[k]});
  }
  for (std::size_t j = 0; j < k_plate_light_radii.size(); ++j) {
    const double x = -3.0 + 2.0 * static_cast<double>(j);
    scene.lights.push_back(Sphere{light_row + Vec3{x, 0.0, 0.0}, k_plate_light_radii[j],
                                  static_cast<std::uint32_t>(n + j)});
    scene.radiance.push_back(equal_power_radiance(k_plates_light_power, k_plate_light_radii[j]));
  }
  return scene;
}

/// The scene as chapter 08's figure shows it (plates.png and the study's 16 boxes): the same
/// plates, lights and eye, framed on the plates as Veach's figure is. Looking 27.5 degrees
/// down into a 20-degree field of view, the plates (36 to 19 degrees below the eye's horizon)
/// fill the frame from top to bottom, the near ones wider than it; every highlight is in view
/// (the outer ones a fifth of the width in from the edges), the lights (on the horizon) are
/// not. make_veach_plates' own view, with the lights in the picture, stays that of the
/// veach-plates scene and of assignment a6, whose references were measured through it.
inline VeachPlates make_veach_plates_figure() {
  VeachPlates scene = make_veach_plates();
  scene.camera.direction = Vec3{0.0, -std::tan(0.48), -1.0};
  scene.camera.vertical_fov = 0.35;
  return scene;
}

/// The first plate or light the ray meets in `range`, if any: a loop over the eight shapes.
inline std::optional<Hit> closest_hit(const VeachPlates& scene, const Ray& ray,
                                      Interval range = {}) {
  std::optional<Hit> best;
  for (const Quad& q : scene.plates)
    if (const std::optional<double> t = intersect_distance(q, ray, range)) {
      range.max = *t;
      best = hit_at(q, ray, *t);
    }
  for (const Sphere& s : scene.lights)
    if (const std::optional<double> t = intersect_distance(s, ray, range)) {
      range.max = *t;
      best = hit_at(s, ray, *t);
    }
  return best;
}

/// A box of pixels [x0, x1) x [y0, y1) around the highlight of one light in one plate.
struct PlateRegion {
  std::size_t plate = 0, light = 0;
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  int pixel_count() const { return std::max(0, x1 - x0) * std::max(0, y1 - y0); }
};

/// The pixel position (x right, y down, in pixels) where the point p shows in a width x height
/// image of the camera: generate_ray's map run backwards (p - eye divided by its component
/// along the view direction lands on the unit-distance screen).
inline Vec2 project_to_pixel(const CameraSpec& spec, int width, int height, const Vec3& p) {
  const Vec3 forward = glm::normalize(spec.direction);
  const Vec3 right = glm::normalize(glm::cross(forward, spec.up));
  const Vec3 up = glm::cross(right, forward);
  const double half_height = std::tan(0.5 * spec.vertical_fov);
  const double half_width = half_height * width / height;
  const Vec3 d = p - spec.eye;
  const double depth = glm::dot(d, forward);
  const double sx = glm::dot(d, right) / depth, sy = glm::dot(d, up) / depth;
  return {(sx / (2.0 * half_width) + 0.5) * width, (0.5 - sy / (2.0 * half_height)) * height};
}

/// Where light j's centre shows in the mirror of plate k: the mirror image of the centre in
/// the plate's plane, joined to the eye, meets the plane there.
inline Vec3 mirror_highlight(const VeachPlates& scene, std::size_t plate, std::size_t light) {
  const Quad& q = scene.plates[plate];
  const Vec3 n = q.normal(), c = q.center(), l = scene.lights[light].center;
  const Vec3 image = l - 2.0 * glm::dot(l - c, n) * n;
  const Vec3 eye = scene.camera.eye, d = image - eye;
  const double t = glm::dot(c - eye, n) / glm::dot(d, n);
  return eye + t * d;
}

/// The 16 regions, plate-major. Each plate's rows: its projected extent (the rows between its
/// four corners' projections), a quarter trimmed off at the top and bottom so that no region
/// holds an edge pixel that is half background. Its columns: from midway between this light's
/// highlight and the previous one's to midway to the next (the plate's projected ends for the
/// outer two), so the four regions of a plate tile it and each is centred on its highlight.
inline std::vector<PlateRegion> plate_regions(const VeachPlates& scene, int width, int height) {
  std::vector<PlateRegion> regions;
  for (std::size_t k = 0; k < scene.plate_count(); ++k) {
    const Quad& q = scene.plates[k];
    const std::array<Vec3, 4> corners{q.corner(), q.corner() + q.edge_u(), q.corner() + q.edge_v(),
                                      q.corner() + q.edge_u() + q.edge_v()};
    double top = height, bottom = 0.0, left = 0.0, right = width;
    for (const Vec3& c : corners) {
      const Vec2 p = project_to_pixel(scene.camera, width, height, c);
      top = std::min(top, p.y);
      bottom = std::max(bottom, p.y);
      // The plate's ends are slanted in the image: keep the columns inside both of them.
      if (glm::dot(c - q.center(), q.edge_u()) < 0.0)
        left = std::max(left, p.x);
      else
        right = std::min(right, p.x);
    }
    const double trim = 0.25 * (bottom - top);
    const int y0 = static_cast<int>(std::ceil(top + trim));
    const int y1 = std::max(y0 + 1, static_cast<int>(std::floor(bottom - trim)));
    std::vector<double> centres;
    for (std::size_t j = 0; j < scene.light_count(); ++j)
      centres.push_back(
          project_to_pixel(scene.camera, width, height, mirror_highlight(scene, k, j)).x);
    for (std::size_t j = 0; j < centres.size(); ++j) {
      const double from = j == 0 ? left : 0.5 * (centres[j - 1] + centres[j]);
      const double to = j + 1 == centres.size() ? right : 0.5 * (centres[j] + centres[j + 1]);
      PlateRegion r;
      r.plate = k;
      r.light = j;
      r.x0 = std::clamp(static_cast<int>(std::ceil(from)), 0, width);
      r.x1 = std::clamp(static_cast<int>(std::floor(to)), 0, width);
      r.y0 = std::clamp(y0, 0, height);
      r.y1 = std::clamp(y1, 0, height);
      regions.push_back(r);
    }
  }
  return regions;
}

/// relative MSE (render/relative_error.hpp) over the pixels of one region only:
/// mean of (A - R)^2 / (R^2 + 0.01) over its pixels and channels.
inline double region_relative_mse(const Image& a, const Image& reference, const PlateRegion& r) {
  double sum = 0.0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (int c = 0; c < 3; ++c) {
        const double ref = reference.at(x, y)[c], d = a.at(x, y)[c] - ref;
        sum += d * d / (ref * ref + 0.01);
      }
  return r.pixel_count() > 0 ? sum / (3.0 * r.pixel_count()) : 0.0;
}

/// The mean of average(pixel) over one region.
inline double region_mean(const Image& image, const PlateRegion& r) {
  double sum = 0.0;
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x) sum += average(image.at(x, y));
  return r.pixel_count() > 0 ? sum / r.pixel_count() : 0.0;
}

}  // namespace mcrt
