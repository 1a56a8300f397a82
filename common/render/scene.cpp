#include "render/scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/cpu_features.hpp"
#include "render/veach_plates.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace mcrt {

std::uint32_t Scene::add_material(const Material& m) {
  materials.push_back(m);
  return static_cast<std::uint32_t>(materials.size() - 1);
}

void Scene::add_sphere(const Sphere& s) {
  if (materials[s.material].is_emitter())
    emitters_.push_back(
        {Emitter::sphere, spheres_.size(), Vec3(0, -1, 0), 2.0 * s.radius, false, false, {}});
  add_to_sphere_list(s);
}

// The part of the light's surface (centre c, radius R) inside the enclosing ball (centre b,
// radius rho) is the cap beyond the plane of the circle where the two surfaces meet. That
// plane lies at distance t from c along a = (b - c) / |b - c|, where both |p - c| = R and
// |p - b| = rho:  t = (d^2 + R^2 - rho^2) / (2 d),  d = |b - c|,  so the cap's height is R - t.
// d^2 - rho^2 is formed as (d - rho)(d + rho): d and rho are both about 1e5 for the ceiling.
void Scene::add_sphere_light(const Sphere& s, std::size_t enclosure) {
  const Sphere& ball = spheres_.at(enclosure);
  const Vec3 to_ball = ball.center - s.center;
  const double d = glm::length(to_ball);
  const double t = ((d - ball.radius) * (d + ball.radius) + s.radius * s.radius) / (2.0 * d);
  const double height = std::clamp(s.radius - t, 0.0, 2.0 * s.radius);
  emitters_.push_back({Emitter::sphere, spheres_.size(), to_ball / d, height, false, true, ball});
  add_to_sphere_list(s);
}

void Scene::add_to_sphere_list(const Sphere& s) {
  spheres_.push_back(s);
  sphere_set_.add(s);
  LaneRecord record;
  for (int axis = 0; axis < 3; ++axis) record.center_and_inverse_radius[axis] = s.center[axis];
  record.center_and_inverse_radius[3] = sphere_set_.inverse_radius(spheres_.size() - 1);
  record.front_material = record.back_material = s.material;
  sphere_records_.push_back(record);
}

void Scene::add_quad(const Quad& q) { add_quad(q, q.material()); }

void Scene::add_quad(const Quad& q, std::uint32_t back_material) {
  add_to_quad_list(q, back_material);
  quad_set_.add(q);
}

void Scene::add_quad_group(std::span<const Quad> quads) {
  for (const Quad& q : quads) add_to_quad_list(q, q.material());
  quad_set_.add_group(quads);
}

void Scene::add_small_quad(const Quad& q, std::uint32_t back_material) {
  add_to_quad_list(q, back_material);
  quad_set_.add_group({&q, 1});
}

void Scene::add_to_quad_list(const Quad& q, std::uint32_t back_material) {
  if (materials[q.material()].is_emitter()) {
    const bool one_sided = !materials[back_material].is_emitter();
    emitters_.push_back({Emitter::quad, quads_.size(), q.normal(), 0.0, one_sided, false, {}});
  }
  quads_.push_back(q);
  quad_back_materials_.push_back(back_material);
  LaneRecord record;
  for (int axis = 0; axis < 3; ++axis) record.normal[axis] = q.normal()[axis];
  record.front_material = q.material();
  record.back_material = back_material;
  quad_records_.push_back(record);
}

// Some primitive is hit in range exactly when a nearest one exists; the four-wide searches
// answer that faster than a loop that stops at the first hit.
bool Scene::any_hit(const Ray& ray, Interval range) const {
  return sphere_set_.nearest(ray, range).index != sphere_set_.size() ||
         quad_set_.nearest(ray, range).index != quad_set_.size();
}

void Scene::hits_in_lanes(const ClosestLanes& nearest, const RayLanes& rays, HitLanes& hits) const {
  static const bool avx2 = cpu_has_avx2();
  if (avx2)
    hits_in_lanes_avx2(nearest, rays, hits);
  else
    hits_in_lanes_portable(nearest, rays, hits);
}

void Scene::hits_in_lanes_portable(const ClosestLanes& nearest, const RayLanes& rays,
                                   HitLanes& hits) const {
  for (int l = 0; l < RayLanes::k_lanes; ++l) {
    const std::optional<Hit> hit = hit_in_lane(nearest, l, rays.get(l));
    hits.material[l] = hit ? static_cast<std::int64_t>(hit->material) : -1;
    if (!hit) continue;
    for (int axis = 0; axis < 3; ++axis) {
      hits.point[axis][l] = hit->point[axis];
      hits.normal[axis][l] = hit->normal[axis];
    }
  }
}

#if defined(__x86_64__)

namespace {

// The four rows of four doubles, one per lane, as four vectors, one per column.
[[gnu::target("avx2")]] inline void transpose(const double* row0, const double* row1,
                                              const double* row2, const double* row3,
                                              __m256d column[4]) {
  const __m256d r0 = _mm256_load_pd(row0), r1 = _mm256_load_pd(row1);
  const __m256d r2 = _mm256_load_pd(row2), r3 = _mm256_load_pd(row3);
  const __m256d x01z01 = _mm256_unpacklo_pd(r0, r1), y01w01 = _mm256_unpackhi_pd(r0, r1);
  const __m256d x23z23 = _mm256_unpacklo_pd(r2, r3), y23w23 = _mm256_unpackhi_pd(r2, r3);
  column[0] = _mm256_permute2f128_pd(x01z01, x23z23, 0x20);
  column[1] = _mm256_permute2f128_pd(y01w01, y23w23, 0x20);
  column[2] = _mm256_permute2f128_pd(x01z01, x23z23, 0x31);
  column[3] = _mm256_permute2f128_pd(y01w01, y23w23, 0x31);
}

}  // namespace

// hit_at of each lane's primitive, four lanes per instruction: each lane's record (its
// sphere's centre and 1/r, or its quad's normal, and its materials) is loaded whole and the
// four are transposed; then the point o + t d, a sphere's normal (p - c) / r, face_forward and
// a quad's side run on the four lanes in the one-lane order.
[[gnu::target("avx2")]] void Scene::hits_in_lanes_avx2(const ClosestLanes& nearest,
                                                       const RayLanes& rays, HitLanes& hits) const {
  constexpr int k_lanes = RayLanes::k_lanes;
  static const LaneRecord miss;  // a lane that hit nothing: material -1, and zeros
  const LaneRecord* of[k_lanes];
  for (int l = 0; l < k_lanes; ++l)
    of[l] = nearest.quad.found(l)     ? &quad_records_[nearest.quad.primitive(l)]
            : nearest.sphere.found(l) ? &sphere_records_[nearest.sphere.primitive(l)]
                                      : &miss;
  __m256d c[4], q[4];  // c[3] is 1 / r
  transpose(of[0]->center_and_inverse_radius, of[1]->center_and_inverse_radius,
            of[2]->center_and_inverse_radius, of[3]->center_and_inverse_radius, c);
  transpose(of[0]->normal, of[1]->normal, of[2]->normal, of[3]->normal, q);

  const __m256d is_quad =
      _mm256_cmp_pd(_mm256_load_pd(nearest.quad.index), _mm256_setzero_pd(), _CMP_GE_OQ);
  const __m256d lane_t =
      _mm256_blendv_pd(_mm256_load_pd(nearest.sphere.t), _mm256_load_pd(nearest.quad.t), is_quad);
  const __m256d d[3] = {_mm256_load_pd(rays.direction_x), _mm256_load_pd(rays.direction_y),
                        _mm256_load_pd(rays.direction_z)};
  const __m256d o[3] = {_mm256_load_pd(rays.origin_x), _mm256_load_pd(rays.origin_y),
                        _mm256_load_pd(rays.origin_z)};
  __m256d p[3], n[3];
  for (int axis = 0; axis < 3; ++axis) {
    p[axis] = _mm256_add_pd(o[axis], _mm256_mul_pd(lane_t, d[axis]));  // ray.at(t)
    n[axis] =
        _mm256_blendv_pd(_mm256_mul_pd(_mm256_sub_pd(p[axis], c[axis]), c[3]), q[axis], is_quad);
  }
  // face_forward: n where n.d <= 0, else -n (the sign bit flipped). For a quad, n.d is the dot
  // of quad_face_material, whose back it meets where n.d > 0 (a sphere's back is its front).
  const __m256d n_dot_d =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(n[0], d[0]), _mm256_mul_pd(n[1], d[1])),
                    _mm256_mul_pd(n[2], d[2]));
  const __m256d facing = _mm256_cmp_pd(n_dot_d, _mm256_setzero_pd(), _CMP_LE_OQ);
  for (int axis = 0; axis < 3; ++axis) {
    const __m256d flipped = _mm256_xor_pd(n[axis], _mm256_set1_pd(-0.0));
    _mm256_store_pd(hits.point[axis], p[axis]);
    _mm256_store_pd(hits.normal[axis], _mm256_blendv_pd(flipped, n[axis], facing));
  }
  const __m256i front = _mm256_setr_epi64x(of[0]->front_material, of[1]->front_material,
                                           of[2]->front_material, of[3]->front_material);
  const __m256i back = _mm256_setr_epi64x(of[0]->back_material, of[1]->back_material,
                                          of[2]->back_material, of[3]->back_material);
  const __m256d from_behind = _mm256_cmp_pd(n_dot_d, _mm256_setzero_pd(), _CMP_GT_OQ);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(hits.material),
                      _mm256_castpd_si256(_mm256_blendv_pd(_mm256_castsi256_pd(front),
                                                           _mm256_castsi256_pd(back),
                                                           from_behind)));
}

#else

void Scene::hits_in_lanes_avx2(const ClosestLanes& nearest, const RayLanes& rays,
                               HitLanes& hits) const {
  hits_in_lanes_portable(nearest, rays, hits);
}

#endif

const std::vector<std::string>& scene_names() {
  static const std::vector<std::string> names{"cornell", "cornell-spheres", "furnace",
                                              "veach-plates", "smallpt"};
  return names;
}

const std::vector<std::string>& diffuse_scene_names() {
  static const std::vector<std::string> names{"cornell", "cornell-spheres", "furnace"};
  return names;
}

Scene make_scene(std::string_view name, const SceneParams& params) {
  if (name == "cornell") return make_cornell_box(params.light_scale);
  if (name == "cornell-spheres") return make_cornell_spheres();
  if (name == "furnace") return make_furnace(params.furnace_albedo, params.furnace_emission);
  if (name == "veach-plates") return make_veach_plates_scene();
  if (name == "smallpt") return make_smallpt();
  throw std::invalid_argument("unknown scene '" + std::string(name) + "'");
}

namespace {

// An axis-aligned box [0,size] turned by `angle` radians about +y and moved to `offset`:
// six quads, in one group (rays that miss the box skip all six).
void add_box(Scene& scene, Vec3 size, double angle, Vec3 offset, std::uint32_t material) {
  const double c = std::cos(angle), s = std::sin(angle);
  auto place = [&](Vec3 p) { return Vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z) + offset; };
  auto turn = [&](Vec3 v) { return Vec3(c * v.x + s * v.z, v.y, -s * v.x + c * v.z); };
  const Vec3 dx = turn({size.x, 0, 0}), dy{0, size.y, 0}, dz = turn({0, 0, size.z});
  const Vec3 o = place({0, 0, 0});
  const Vec3 far = place(size);
  const Quad faces[] = {
      {o, dx, dy, material},      // front
      {o, dz, dy, material},      // left
      {o, dx, dz, material},      // bottom
      {far, -dx, -dy, material},  // back
      {far, -dz, -dy, material},  // right
      {far, -dx, -dz, material},  // top
  };
  scene.add_quad_group(faces);
}

}  // namespace

// The Cornell box in the dimensions of the Cornell data (a 555-unit cube, open at the front),
// with the two boxes placed as in "Ray Tracing: The Next Week". The lamp is one-sided: it
// emits downwards, and its back (towards the ceiling) is black. Light scale s: the lamp's sides
// times s about its centre, its radiance 15 / s^2, so its power pi Le A stays the same.
// lamp_parts cuts the lamp into that many strips side by side, each an emitter of its own: the
// same light and the same picture, but a light sampler must choose among the strips (the
// grading of a5.3 uses two).
Scene make_cornell_box(double light_scale, int lamp_parts) {
  if (!(light_scale > 0.0 && light_scale <= k_max_light_scale))
    throw std::invalid_argument("light scale must be in (0, 4]");
  if (lamp_parts < 1) throw std::invalid_argument("the lamp has at least one part");
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
  scene.add_quad({{l, 0, 0}, {0, l, 0}, {0, 0, l}, red});    // left wall, x = 555
  scene.add_quad({{0, 0, 0}, {0, l, 0}, {0, 0, l}, green});  // right wall, x = 0
  scene.add_quad({{0, 0, 0}, {l, 0, 0}, {0, 0, l}, white});  // floor
  scene.add_quad({{0, l, 0}, {l, 0, 0}, {0, 0, l}, white});  // ceiling
  scene.add_quad({{0, 0, l}, {l, 0, 0}, {0, l, 0}, white});  // back wall
  // The light, 130 x 105 (times s), centred at (278, 554, 279.5) just below the ceiling; edge
  // order makes its normal point down.
  const Vec3 lamp_centre(278, l - 1, 279.5), u(130 * light_scale, 0, 0), v(0, 0, 105 * light_scale);
  const Quad lamp{lamp_centre - 0.5 * (u + v), u, v, light};
  for (int i = 0; i < lamp_parts; ++i) {  // 4 % of the ceiling: its bounds spare most tests
    const Vec3 strip = u / static_cast<double>(lamp_parts);
    const Quad part(lamp.corner() + static_cast<double>(i) * strip, strip, v, light);
    scene.add_small_quad(part, lamp_back);
  }
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

namespace {

// smallpt's box of nine spheres, with `left_ball` and `right_ball` the materials of its two
// balls (smallpt's mirror and glass) and smallpt's camera.
Scene make_sphere_box(std::string name, const Material& left_ball, const Material& right_ball) {
  Scene scene;
  scene.name = std::move(name);
  auto diffuse = [&](Color albedo) { return scene.add_material({albedo, Color(0.0)}); };
  const auto left = diffuse({.75, .25, .25});
  const auto right = diffuse({.25, .25, .75});
  const auto grey = diffuse(Color(.75));
  const auto black = diffuse(Color(0.0));
  const auto left_ball_material = scene.add_material(left_ball);
  const auto right_ball_material = scene.add_material(right_ball);
  const Color le(12.0);
  const auto light = scene.add_material({Color(0.0), le});
  const Sphere spheres[] = {
      {{1e5 + 1, 40.8, 81.6}, 1e5, left},           // left wall
      {{-1e5 + 99, 40.8, 81.6}, 1e5, right},        // right wall
      {{50, 40.8, 1e5}, 1e5, grey},                 // back wall
      {{50, 40.8, -1e5 + 170}, 1e5, black},         // front wall
      {{50, 1e5, 81.6}, 1e5, grey},                 // floor
      {{50, -1e5 + 81.6, 81.6}, 1e5, grey},         // ceiling
      {{27, 16.5, 47}, 16.5, left_ball_material},   // left ball (smallpt's mirror)
      {{73, 16.5, 78}, 16.5, right_ball_material},  // right ball (smallpt's glass)
  };
  for (const Sphere& s : spheres) scene.add_sphere(s);
  // The light: a 600-radius sphere whose bottom pokes 0.27 below the ceiling plane; the
  // ceiling (a 1e5-radius sphere, index 5) hides the rest from the room.
  const double cap_height = 0.27;
  scene.add_sphere_light({{50, 681.6 - cap_height, 81.6}, 600, light}, 5);
  // smallpt's camera; its rays start 140 units from the eye along their direction.
  scene.camera = {
      {50, 52, 295.6}, {0, -0.042612, -1}, {0, 1, 0}, 2.0 * std::atan(0.5135 / 2.0), 140.0};
  // The light is the cap of the 600-radius sphere below the ceiling (y = 81.6): height
  // h = 0.27, area 2 pi R h, nearly flat (15 times wider than deep). Its point light sits just
  // under the cap's lowest point with the far field of a flat light of that area facing down,
  // I(theta) = Le A cos(theta) (see make_cornell_box).
  const double cap_area = k_two_pi * 600.0 * cap_height;
  scene.point_light = {{50, 81.6 - cap_height - 1e-3, 81.6}, le * cap_area, Vec3(0, -1, 0)};
  return scene;
}

}  // namespace

// smallpt's scene with every material diffuse (mirror and glass become albedo 0.999).
Scene make_cornell_spheres() {
  const Material white{Color(.999), Color(0.0)};
  return make_sphere_box("cornell-spheres", white, white);
}

// smallpt's scene itself: its left ball a mirror, its right ball glass of index 1.5, both of
// tint 0.999. The glass reflects by Schlick's approximation, as smallpt's does, so that the
// two renderers estimate the same image (render/fresnel.hpp).
Scene make_smallpt() {
  Material mirror, glass;
  mirror.delta = Delta::mirror;
  glass.delta = Delta::dielectric;
  mirror.tint = glass.tint = Color(.999);
  glass.ior = 1.5;
  glass.fresnel = FresnelModel::schlick;
  return make_sphere_box("smallpt", mirror, glass);
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

// Veach's plates, from make_veach_plates(): its material numbering (plate k has material k,
// light j material plates + j) is kept by adding the plates' materials first, then the
// lights', so its quads and spheres go in unchanged. Plates are two-sided, as its closest_hit
// sees them; the lights are whole spheres (no enclosure), and there is no point light.
Scene make_veach_plates_scene() {
  const VeachPlates plates = make_veach_plates();
  Scene scene;
  scene.name = "veach-plates";
  for (const Phong& p : plates.materials)
    scene.add_material({Color(p.rho_d), Color(0.0), p.rho_s, p.m});
  for (double le : plates.radiance) scene.add_material({Color(0.0), Color(le)});
  for (const Quad& q : plates.plates) scene.add_quad(q);
  for (const Sphere& s : plates.lights) scene.add_sphere(s);
  scene.camera = plates.camera;
  scene.point_light = {Vec3(0.0), Color(0.0)};  // the lights are spheres; no point light
  return scene;
}

}  // namespace mcrt
