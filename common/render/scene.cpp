#include "render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mcrt {

std::uint32_t Scene::add_material(const Material& m) {
  materials.push_back(m);
  return static_cast<std::uint32_t>(materials.size() - 1);
}

void Scene::add_sphere(const Sphere& s) {
  if (materials[s.material].is_emitter())
    emitters_.push_back({Emitter::sphere, spheres_.size(), Vec3(0, -1, 0), 2.0 * s.radius, false});
  spheres_.push_back(s);
  sphere_set_.add(s);
}

void Scene::add_sphere_light(const Sphere& s, const Vec3& cap_axis, double cap_height) {
  emitters_.push_back({Emitter::sphere, spheres_.size(), cap_axis, cap_height, false});
  spheres_.push_back(s);
  sphere_set_.add(s);
}

void Scene::add_quad(const Quad& q) { add_quad(q, q.material()); }

void Scene::add_quad(const Quad& q, std::uint32_t back_material) {
  if (materials[q.material()].is_emitter()) {
    const bool one_sided = !materials[back_material].is_emitter();
    emitters_.push_back({Emitter::quad, quads_.size(), q.normal(), 0.0, one_sided});
  }
  quads_.push_back(q);
  quad_set_.add(q);
  quad_back_materials_.push_back(back_material);
}

// Some primitive is hit in range exactly when a nearest one exists; the four-wide searches
// answer that faster than a loop that stops at the first hit.
bool Scene::any_hit(const Ray& ray, Interval range) const {
  return sphere_set_.nearest(ray, range).index != sphere_set_.size() ||
         quad_set_.nearest(ray, range).index != quad_set_.size();
}

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names{"cornell", "cornell-spheres", "furnace"};
  return names;
}

Scene make_scene(std::string_view name, const SceneParams& params) {
  if (name == "cornell") return make_cornell_box(params.light_scale);
  if (name == "cornell-spheres") return make_cornell_spheres();
  if (name == "furnace") return make_furnace(params.furnace_albedo, params.furnace_emission);
  throw std::invalid_argument("unknown scene '" + std::string(name) + "'");
}

namespace {

// An axis-aligned box [0,size] turned by `angle` radians about +y and moved to `offset`:
// six quads.
void add_box(Scene& scene, Vec3 size, double angle, Vec3 offset, std::uint32_t material) {
  const double c = std::cos(angle), s = std::sin(angle);
  auto place = [&](Vec3 p) { return Vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z) + offset; };
  auto turn = [&](Vec3 v) { return Vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z); };
  const Vec3 dx = turn({size.x, 0, 0}), dy{0, size.y, 0}, dz = turn({0, 0, size.z});
  const Vec3 o = place({0, 0, 0});
  const Vec3 far = place(size);
  scene.add_quad({o, dx, dy, material});         // front
  scene.add_quad({o, dz, dy, material});         // left
  scene.add_quad({o, dx, dz, material});         // bottom
  scene.add_quad({far, -dx, -dy, material});     // back
  scene.add_quad({far, -dz, -dy, material});     // right
  scene.add_quad({far, -dx, -dz, material});     // top
}

}  // namespace

// The Cornell box in the dimensions of the Cornell data (a 555-unit cube, open at the front),
// with the two boxes placed as in "Ray Tracing: The Next Week". The lamp is one-sided: it
// emits downwards, and its back (towards the ceiling) is black. Light scale s: the lamp's sides
// times s about its centre, its radiance 15 / s^2, so its power pi Le A stays the same.
Scene make_cornell_box(double light_scale) {
  if (!(light_scale > 0.0 && light_scale <= k_max_light_scale))
    throw std::invalid_argument("light scale must be in (0, 4]");
  Scene scene;
  scene.name = "cornell";
  const auto red = scene.add_material({Color(0.65, 0.05, 0.05), Color(0.0)});
  const auto white = scene.add_material({Color(0.73), Color(0.0)});
  const auto green = scene.add_material({Color(0.12, 0.45, 0.15), Color(0.0)});
  const Color le(15.0 / (light_scale * light_scale));
  const auto light = scene.add_material({Color(0.0), le});
  const auto lamp_back = scene.add_material({Color(0.0), Color(0.0)});

  const double l = 555.0;
  // The camera looks along +z with y up, so x = 555 is on the left of the image.
  scene.add_quad({{l, 0, 0}, {0, l, 0}, {0, 0, l}, red});     // left wall, x = 555
  scene.add_quad({{0, 0, 0}, {0, l, 0}, {0, 0, l}, green});   // right wall, x = 0
  scene.add_quad({{0, 0, 0}, {l, 0, 0}, {0, 0, l}, white});   // floor
  scene.add_quad({{0, l, 0}, {l, 0, 0}, {0, 0, l}, white});   // ceiling
  scene.add_quad({{0, 0, l}, {l, 0, 0}, {0, l, 0}, white});   // back wall
  // The light, 130 x 105 (times s), centred at (278, 554, 279.5) just below the ceiling; edge
  // order makes its normal point down.
  const Vec3 lamp_centre(278, l - 1, 279.5), u(130 * light_scale, 0, 0), v(0, 0, 105 * light_scale);
  const Quad lamp{lamp_centre - 0.5 * (u + v), u, v, light};
  scene.add_quad(lamp, lamp_back);
  add_box(scene, {165, 330, 165}, 15.0 * k_pi / 180.0, {265, 0, 295}, white);
  add_box(scene, {165, 165, 165}, -18.0 * k_pi / 180.0, {130, 0, 65}, white);

  // Looking in through the open front: 40 degrees vertical field of view.
  scene.camera = {{278, 278, -800}, {0, 0, 1}, {0, 1, 0}, 40.0 * k_pi / 180.0, 0.0};
  // Seen from afar, a flat one-sided light of radiance Le and area A is a point of intensity
  // I(theta) = Le A cos(theta) about its normal (power: integral of I over the hemisphere,
  // pi Le A, the area light's).
  scene.point_light = {lamp.center() - Vec3(0, 1e-3, 0), le * lamp.area(), lamp.normal()};
  return scene;
}

// smallpt's scene with every material diffuse (mirror and glass become albedo 0.999).
Scene make_cornell_spheres() {
  Scene scene;
  scene.name = "cornell-spheres";
  auto diffuse = [&](Color albedo) { return scene.add_material({albedo, Color(0.0)}); };
  const auto left = diffuse({.75, .25, .25});
  const auto right = diffuse({.25, .25, .75});
  const auto grey = diffuse(Color(.75));
  const auto black = diffuse(Color(0.0));
  const auto white = diffuse(Color(.999));
  const Color le(12.0);
  const auto light = scene.add_material({Color(0.0), le});
  const Sphere spheres[] = {
      {{1e5 + 1, 40.8, 81.6}, 1e5, left},      // left wall
      {{-1e5 + 99, 40.8, 81.6}, 1e5, right},   // right wall
      {{50, 40.8, 1e5}, 1e5, grey},            // back wall
      {{50, 40.8, -1e5 + 170}, 1e5, black},    // front wall
      {{50, 1e5, 81.6}, 1e5, grey},            // floor
      {{50, -1e5 + 81.6, 81.6}, 1e5, grey},    // ceiling
      {{27, 16.5, 47}, 16.5, white},           // left sphere (smallpt's mirror)
      {{73, 16.5, 78}, 16.5, white},           // right sphere (smallpt's glass)
  };
  for (const Sphere& s : spheres) scene.add_sphere(s);
  // The light: a sphere whose cap 0.27 deep pokes through the ceiling; only that cap is seen.
  const double cap_height = 0.27;
  scene.add_sphere_light({{50, 681.6 - cap_height, 81.6}, 600, light}, Vec3(0, -1, 0), cap_height);
  scene.camera = {{50, 52, 295.6}, {0, -0.042612, -1}, {0, 1, 0}, 2.0 * std::atan(0.5135 / 2.0),
                  140.0};
  // The light is the cap of the 600-radius sphere below the ceiling (y = 81.6): height
  // h = 0.27, area 2 pi R h, nearly flat (15 times wider than deep). Its point light sits just
  // under the cap's lowest point with the far field of a flat light of that area facing down,
  // I(theta) = Le A cos(theta) (see make_cornell_box).
  const double cap_area = k_two_pi * 600.0 * cap_height;
  scene.point_light = {{50, 81.6 - cap_height - 1e-3, 81.6}, le * cap_area, Vec3(0, -1, 0)};
  return scene;
}

// The inside of a unit sphere, albedo a and emission Le everywhere: every path bounces forever
// and the radiance after k bounces is Le (1 + a + ... + a^k), the same in every direction.
// The whole sphere is its one emitter, two-sided (it is seen from inside).
Scene make_furnace(double albedo, double emission) {
  Scene scene;
  scene.name = "furnace";
  const auto m = scene.add_material({Color(albedo), Color(emission)});
  scene.add_sphere({Vec3(0.0), 1.0, m});
  scene.camera = {Vec3(0.0), {0, 0, -1}, {0, 1, 0}, 60.0 * k_pi / 180.0, 0.0};
  scene.point_light = {Vec3(0.0), Color(0.0)};  // the walls are the light; no point light
  return scene;
}

}  // namespace mcrt
