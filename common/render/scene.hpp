#pragma once
/// A scene: plain arrays of primitives and materials, closest-hit and any-hit queries, and the
/// built-in scenes every chapter can render by name.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/camera.hpp"
#include "geometry/quad.hpp"
#include "geometry/quad_set.hpp"
#include "geometry/ray_lanes.hpp"
#include "geometry/sphere.hpp"
#include "geometry/sphere_set.hpp"
#include "render/material.hpp"

namespace mcrt {

/// Plain ray tracing's light: a point of radiant intensity I (W/sr). With a normal n it is the
/// far field of a flat one-sided area light (radiance Le, area A) facing n, seen from far away:
/// I(theta) = Le A cos(theta) towards directions at angle theta to n, 0 behind it. With no
/// normal (n = 0) it is isotropic: I in every direction.
struct PointLight {
  Vec3 position{0.0};
  Color intensity{0.0};  ///< I along the normal (Le A), or in every direction if normal is 0
  Vec3 normal{0.0};      ///< the side the light faces; 0 for an isotropic light

  /// I(theta) towards the unit `direction` (from the light outwards).
  Color intensity_towards(const Vec3& direction) const {
    if (normal == Vec3(0.0)) return intensity;
    return intensity * std::max(0.0, glm::dot(normal, direction));
  }
};

/// An emitter the light sampler can aim at: an emissive quad (the whole of it), or an emissive
/// sphere. A sphere may have an ENCLOSURE: an opaque sphere of the scene (cornell-spheres'
/// ceiling) whose inside holds only a cap of the light, {p : (p - c).axis >= R - height} around
/// the unit `cap_axis`; from inside the enclosure that cap is all of the light that can be
/// seen (render/light_sampling.hpp proves it), so light sampling aims at the cap there and at
/// the whole sphere anywhere else. Without an enclosure the cap is the whole sphere (height 2R).
struct Emitter {
  enum Kind { quad, sphere } kind = quad;
  std::size_t index = 0;  ///< into Scene::quads() or Scene::spheres()
  Vec3 cap_axis{0, -1, 0};
  double cap_height = 0.0;
  bool one_sided = false;  ///< emits only on its front (a quad's normal side)
  bool has_enclosure = false;
  Sphere enclosure;  ///< the enclosing ball (centre, radius), when has_enclosure
};

/// Primitives are added through add_sphere / add_quad only, so the structure-of-arrays copy
/// of the spheres that closest_hit reads stays in step with the list, and every emissive
/// primitive lands in emitters().
///
/// One-sided lights: a quad may have a back material, the material of its side against its
/// normal. closest_hit gives a hit from behind the back material, so a lamp whose back is black
/// emits towards its normal only, in every estimator, without any of them asking which side
/// they hit.
struct Scene {
  std::string name;
  std::vector<Material> materials;
  CameraSpec camera;
  PointLight point_light;  ///< the area light seen from afar: its far field Le A cos(theta)

  std::uint32_t add_material(const Material& m);
  void add_sphere(const Sphere& s);
  /// A sphere light sunk into the opaque sphere spheres()[enclosure] (added before it): from
  /// inside that sphere only the cap of the light inside it can be seen. The cap is computed
  /// here, exactly, from the two spheres.
  void add_sphere_light(const Sphere& s, std::size_t enclosure);
  void add_quad(const Quad& q);
  /// A quad whose side against its normal has `back_material` (for a one-sided lamp: black).
  void add_quad(const Quad& q, std::uint32_t back_material);
  /// Quads that enclose a small part of the scene (the faces of a box): added as add_quad adds
  /// each, and the AVX2 searches skip them for rays that miss their common bounds.
  void add_quad_group(std::span<const Quad> quads);
  /// A quad that covers a small part of the scene (a lamp), with `back_material` as add_quad:
  /// behind bounds of its own, like a group of one, so most searches skip it.
  void add_small_quad(const Quad& q, std::uint32_t back_material);

  const std::vector<Sphere>& spheres() const { return spheres_; }
  const std::vector<Quad>& quads() const { return quads_; }
  const std::vector<Emitter>& emitters() const { return emitters_; }
  const Material& material(const Hit& hit) const { return materials[hit.material]; }
  /// The material of quad i's side that a ray of direction d meets.
  std::uint32_t quad_face_material(std::size_t i, const Vec3& d) const {
    return glm::dot(quads_[i].normal(), d) > 0.0 ? quad_back_materials_[i] : quads_[i].material();
  }
  /// Le of emitter e's surface seen from direction `towards` (unit, from the surface to the
  /// viewer) at a point of outward normal n: 0 behind a one-sided emitter.
  Color emitted(const Emitter& e, const Vec3& n, const Vec3& towards) const {
    if (e.one_sided && glm::dot(n, towards) <= 0.0) return Color(0.0);
    return materials[e.kind == Emitter::quad ? quads_[e.index].material()
                                             : spheres_[e.index].material]
        .emission;
  }

  /// The closest surface along the ray within `range`. One call is one traced ray.
  ///
  /// The nearest t over every primitive is found first, and the Hit is built once, for the
  /// winner. The spheres and the quads are each searched four at a time (SphereSet, QuadSet);
  /// ties keep the first primitive, spheres before quads, as the plain loop over
  /// intersect_distance does. Defined here so that it is inlined into the estimators: the Hit
  /// is then built where the estimator keeps it, with no copy per bounce.
  std::optional<Hit> closest_hit(const Ray& ray, Interval range = {}) const {
    const SphereSet::Nearest sphere = sphere_set_.nearest(ray, range);
    range.max = sphere.t;
    const QuadSet::Nearest quad = quad_set_.nearest(ray, range);
    if (quad.index != quad_set_.size()) {
      Hit hit = hit_at(quads_[quad.index], ray, quad.t);
      hit.material = quad_face_material(quad.index, ray.direction);
      return hit;
    }
    if (sphere.index != sphere_set_.size())
      return hit_at(spheres_[sphere.index], ray, sphere.t,
                    sphere_set_.inverse_radius(sphere.index));
    return std::nullopt;
  }

  /// closest_hit of four rays at once, in two steps: the search (closest_hits) and each lane's
  /// Hit (hit_in_lane), which is the same, bit for bit, as closest_hit(rays.get(lane)).
  struct ClosestLanes {
    NearestLanes sphere{Interval{}.max};
    NearestLanes quad{Interval{}.max};  ///< only quads nearer than the lane's sphere
  };
  ClosestLanes closest_hits(const RayLanes& rays) const {
    ClosestLanes nearest;
    sphere_set_.nearest_lanes(rays, Interval{}.min, nearest.sphere);
    for (int l = 0; l < RayLanes::k_lanes; ++l) nearest.quad.t[l] = nearest.sphere.t[l];
    quad_set_.nearest_lanes(rays, Interval{}.min, nearest.quad);
    return nearest;
  }
  std::optional<Hit> hit_in_lane(const ClosestLanes& nearest, int lane, const Ray& ray) const {
    if (nearest.quad.found(lane)) {
      const std::size_t i = nearest.quad.primitive(lane);
      Hit hit = hit_at(quads_[i], ray, nearest.quad.t[lane]);
      hit.material = quad_face_material(i, ray.direction);
      return hit;
    }
    if (nearest.sphere.found(lane)) {
      const std::size_t i = nearest.sphere.primitive(lane);
      return hit_at(spheres_[i], ray, nearest.sphere.t[lane], sphere_set_.inverse_radius(i));
    }
    return std::nullopt;
  }

  /// Every lane's hit_in_lane at once, into `hits`: the same points, normals and materials,
  /// bit for bit. AVX2 where the processor has it.
  void hits_in_lanes(const ClosestLanes& nearest, const RayLanes& rays, HitLanes& hits) const;
  /// One lane at a time, with hit_in_lane.
  void hits_in_lanes_portable(const ClosestLanes& nearest, const RayLanes& rays,
                              HitLanes& hits) const;
  /// Four lanes per instruction; only call it where the processor has AVX2.
  void hits_in_lanes_avx2(const ClosestLanes& nearest, const RayLanes& rays, HitLanes& hits) const;

  /// Whether any surface blocks the ray within `range` (a shadow ray); stops at the first.
  bool any_hit(const Ray& ray, Interval range = {}) const;

 private:
  void add_to_sphere_list(const Sphere& s);
  void add_to_quad_list(const Quad& q, std::uint32_t back_material);

  // What hits_in_lanes_avx2 reads of each lane's primitive: two rows of four doubles, loaded
  // whole and transposed (a sphere's centre and 1 / r; a quad's unit normal), and the
  // materials of its front and back (a sphere's two are the same).
  struct LaneRecord {
    alignas(32) double center_and_inverse_radius[4]{};
    alignas(32) double normal[4]{};
    std::int64_t front_material = -1, back_material = -1;
  };

  std::vector<Sphere> spheres_;
  std::vector<Quad> quads_;
  std::vector<std::uint32_t> quad_back_materials_;
  std::vector<LaneRecord> sphere_records_, quad_records_;  ///< one per sphere, one per quad
  std::vector<Emitter> emitters_;
  SphereSet sphere_set_;  ///< spheres_ as a structure of arrays
  QuadSet quad_set_;      ///< quads_ as a structure of arrays
};

/// Parameters of the built-in scenes that take them.
struct SceneParams {
  double furnace_albedo = 0.5;
  double furnace_emission = 1.0;
  /// cornell: the lamp's sides times s about its centre, its radiance over s^2 (constant
  /// power): 0.1 a tiny bright lamp, 3 a large dim one. At most k_max_light_scale.
  double light_scale = 1.0;
};

/// The largest --light-scale that keeps the lamp (130 x 105 at scale 1) inside the 555-unit
/// ceiling.
inline constexpr double k_max_light_scale = 4.0;

/// The built-in scenes: "cornell", "cornell-spheres", "furnace", "veach-plates", "smallpt".
const std::vector<std::string>& scene_names();

/// The built-in scenes whose materials are all diffuse: every scene but "veach-plates" and
/// "smallpt" (a mirror and glass). The
/// chapters whose estimators see only the diffuse part of a material (f_r = rho / pi: 01, 04,
/// 08's path estimators) offer only these.
const std::vector<std::string>& diffuse_scene_names();

/// Builds the named scene; the name must be one of scene_names().
Scene make_scene(std::string_view name, const SceneParams& params = {});

/// A scene chosen by name, as the flags --scene, --albedo, --emission (and chapter 08's
/// --light-scale) give it.
struct SceneOptions {
  std::string scene = "cornell";
  SceneParams params;
};

Scene make_cornell_box(double light_scale = 1.0, int lamp_parts = 1);
Scene make_cornell_spheres();
/// smallpt's scene as smallpt renders it: cornell-spheres with its left ball a mirror and its
/// right ball glass (index 1.5, Schlick's Fresnel as smallpt's), both of tint 0.999.
Scene make_smallpt();
Scene make_furnace(double albedo, double emission);
/// Veach's plates (render/veach_plates.hpp) as a Scene: the same plates, lights and camera as
/// make_veach_plates(), from which it is built, with each plate's Phong lobe as a Material and
/// each light an emitting sphere. Open: a ray that misses the plates and lights leaves.
Scene make_veach_plates_scene();

}  // namespace mcrt
