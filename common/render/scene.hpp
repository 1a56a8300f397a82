#pragma once
/// A scene: plain arrays of primitives and materials, closest-hit and any-hit queries, and the
/// built-in scenes every chapter can render by name.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/camera.hpp"
#include "geometry/quad.hpp"
#include "geometry/sphere.hpp"
#include "geometry/sphere_set.hpp"
#include "render/material.hpp"

namespace mcrt {

/// An isotropic point light of radiant intensity I (W/sr): plain ray tracing's light.
struct PointLight {
  Vec3 position{0.0};
  Color intensity{0.0};
};

/// Primitives are added through add_sphere / add_quad only, so the structure-of-arrays copy
/// of the spheres that closest_hit reads stays in step with the list.
struct Scene {
  std::string name;
  std::vector<Material> materials;
  CameraSpec camera;
  PointLight point_light;  ///< the area light collapsed to its centre, with the same power

  std::uint32_t add_material(const Material& m);
  void add_sphere(const Sphere& s);
  void add_quad(const Quad& q);

  const std::vector<Sphere>& spheres() const { return spheres_; }
  const std::vector<Quad>& quads() const { return quads_; }
  const Material& material(const Hit& hit) const { return materials[hit.material]; }

  /// The closest surface along the ray within `range`. One call is one traced ray.
  std::optional<Hit> closest_hit(const Ray& ray, Interval range = {}) const;

  /// Whether any surface blocks the ray within `range` (a shadow ray); stops at the first.
  bool any_hit(const Ray& ray, Interval range = {}) const;

 private:
  std::vector<Sphere> spheres_;
  std::vector<Quad> quads_;
  SphereSet sphere_set_;  ///< spheres_ as a structure of arrays
};

/// Parameters of the built-in scenes that take them.
struct SceneParams {
  double furnace_albedo = 0.5;
  double furnace_emission = 1.0;
};

/// The built-in scenes: "cornell", "cornell-spheres", "furnace".
const std::vector<std::string>& scene_names();

/// Builds the named scene; the name must be one of scene_names().
Scene make_scene(std::string_view name, const SceneParams& params = {});

/// A scene chosen by name, as the flags --scene, --albedo and --emission give it.
struct SceneOptions {
  std::string scene = "cornell";
  SceneParams params;
};

Scene make_cornell_box();
Scene make_cornell_spheres();
Scene make_furnace(double albedo, double emission);

}  // namespace mcrt
