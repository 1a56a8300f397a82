#pragma once
/// Light sampling on a scene: pick one of the scene's emitters (uniformly, probability 1/N),
/// a point y on it (sampling/light.hpp, pdf per unit area), and the direct light that point
/// sends to a shading point x through a shadow ray. Shared by next-event estimation and MIS.
///
/// The direct light at x, from the light's side (the area form of the rendering equation):
///
///   Ld(x, wo) = integral over the lights of f_r Le(y -> x) V(x, y) cos(theta_x) cos(theta_y) / r^2 dA(y)
///             ~ f_r Le V cos(theta_x) cos(theta_y) / (r^2 p_A(y))        (one point y ~ p_A)
///             = f_r Le V cos(theta_x) / p_w(wi),   p_w = p_A r^2 / cos(theta_y),
///
/// unbiased wherever p_A > 0 on every light point x can see (E[g / p_A] = integral of g).

#include <cmath>
#include <cstddef>
#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/scene.hpp"
#include "sampling/light.hpp"

namespace mcrt {

/// Shadow rays stop this fraction short of the light point: the light's own surface at t = r
/// must not count as a blocker.
inline constexpr double k_shadow_ray_shortening = 1e-6;

/// Which part of a sphere light is sampled from the point x.
enum class SphereLightPart {
  cap,    ///< x inside the light's enclosure: uniform area on the cap inside it
  cone,   ///< x outside the sphere: uniform solid angle over the cone the sphere subtends
  whole,  ///< x inside the sphere: uniform area on the whole sphere
};

/// The choice, and why each covers every point of the light that x can see (light sampling
/// is unbiased only where p > 0 on all of them: E[g / p] = integral of g over {p > 0}):
///  - cap: the enclosure is a ball whose surface is an opaque sphere of the scene, and x is
///    strictly inside it. A ball is convex, so the segment from x to any point outside it
///    crosses that surface and is blocked: x sees only light points inside the ball, and those
///    are exactly the cap (Scene::add_sphere_light). A point outside the enclosure sees the
///    light beyond the cap: cornell-spheres' camera rays start 140 units in front of the eye,
///    and the top rows' start above the ceiling, where they meet the walls between the ceiling
///    and the light; they take one of the two choices below.
///  - cone: from x outside the sphere only its near side can be seen, and every point of the
///    near side is met by a direction of the cone.
///  - whole: from x inside the sphere anything may be seen, and the whole sphere is sampled.
/// x is the origin of the rays that leave the shading point on its normal's side (the shadow
/// ray, the BSDF-sampled ray), so the sampler and light_pdf_towards choose alike.
inline SphereLightPart sphere_light_part(const Sphere& s, const Emitter& e, const Vec3& x) {
  if (e.has_enclosure) {
    const Vec3 to_x = x - e.enclosure.center;
    if (glm::dot(to_x, to_x) < e.enclosure.radius * e.enclosure.radius) return SphereLightPart::cap;
  }
  const Vec3 to_x = x - s.center;
  return glm::dot(to_x, to_x) > s.radius * s.radius ? SphereLightPart::cone
                                                    : SphereLightPart::whole;
}

/// A point y on emitter `e` for the shading point x (see sphere_light_part), drawn by u.
inline LightPoint sample_emitter(const Scene& scene, const Emitter& e, const Vec3& x, Vec2 u) {
  if (e.kind == Emitter::quad) {
    const Quad& q = scene.quads()[e.index];
    return sample_quad(q.corner(), q.edge_u(), q.edge_v(), u);
  }
  const Sphere& s = scene.spheres()[e.index];
  switch (sphere_light_part(s, e, x)) {
    case SphereLightPart::cap:
      return sample_sphere_cap(s.center, s.radius, e.cap_axis, e.cap_height, u);
    case SphereLightPart::cone: return sample_sphere_cone(s.center, s.radius, x, u);
    case SphereLightPart::whole: break;
  }
  return sample_sphere_cap(s.center, s.radius, e.cap_axis, 2.0 * s.radius, u);
}

/// p_w(y) per steradian at x of the point y on emitter e that x sees at distance r and angle
/// theta_y to the light's normal: what sample_emitter gives that direction (0 for a point the
/// sampler does not cover: a point of the sphere outside its cap, seen from inside the
/// enclosure, which the enclosure hides anyway).
inline double emitter_pdf_solid_angle(const Scene& scene, const Emitter& e, const Vec3& x,
                                      const Vec3& y, double distance, double cos_y) {
  if (e.kind == Emitter::quad)
    return area_to_solid_angle_pdf(quad_pdf_area(scene.quads()[e.index].area()), distance, cos_y);
  const Sphere& s = scene.spheres()[e.index];
  switch (sphere_light_part(s, e, x)) {
    case SphereLightPart::cap: {
      const double z = glm::dot(y - s.center, e.cap_axis) / s.radius;
      if (z < 1.0 - e.cap_height / s.radius - 1e-9) return 0.0;
      return area_to_solid_angle_pdf(sphere_cap_pdf_area(s.radius, e.cap_height), distance, cos_y);
    }
    case SphereLightPart::cone: return sphere_cone_pdf_solid_angle(s.center, s.radius, x);
    case SphereLightPart::whole: break;
  }
  return area_to_solid_angle_pdf(sphere_cap_pdf_area(s.radius, 2.0 * s.radius), distance, cos_y);
}

/// One light sample seen from a shading point: the direction wi to y, Le(y -> x) (0 behind a
/// one-sided light), cos(theta_x), and p_w(wi) per steradian (emitter choice included).
/// `visible` is false when the shadow ray was blocked or not traced.
struct DirectSample {
  Vec3 wi{0.0};
  Color le{0.0};
  double cos_x = 0.0;
  double pdf_light = 0.0;  ///< p_w(wi) = (1/N) p_A(y) r^2 / cos(theta_y)
  bool visible = false;

  bool contributes() const { return visible && pdf_light > 0.0 && le != Color(0.0); }
};

/// Picks an emitter and a point y on it, and traces the shadow ray from the hit to y (counted
/// in `count`) when y could light the hit: in front of the surface and of the light.
inline DirectSample sample_direct_light(const Scene& scene, const Hit& hit, Rng& rng,
                                        RayCount& count) {
  // ASSIGNMENT a5.3 BEGIN stub: (void)scene; (void)hit; (void)rng; (void)count; NOT_IMPLEMENTED(sample_direct_light);
  DirectSample d;
  const std::size_t n = scene.emitters().size();
  const double u_pick = rng.uniform();
  const Vec2 u = rng.uniform2();
  if (n == 0) return d;
  const auto pick = static_cast<std::size_t>(u_pick * static_cast<double>(n));
  const Emitter& e = scene.emitters()[std::min(n - 1, pick)];
  const Vec3 x = spawn_ray(hit, hit.normal).origin;  // where rays leave the hit (its lit side)
  const LightPoint y = sample_emitter(scene, e, x, u);
  const auto [shadow_ray, distance] = spawn_ray_to(hit, y.point);
  d.wi = shadow_ray.direction;
  d.cos_x = glm::dot(hit.normal, d.wi);
  const double cos_y = glm::dot(y.normal, -d.wi);  // signed: < 0 is the light's back
  d.le = scene.emitted(e, y.normal, -d.wi);
  if (d.cos_x <= 0.0 || d.le == Color(0.0)) return d;  // behind the surface, or the light's back
  d.pdf_light = area_to_solid_angle_pdf(y.pdf_area / static_cast<double>(n), distance, cos_y);
  ++count.rays;
  d.visible = !scene.any_hit(shadow_ray, {1e-9, distance * (1.0 - k_shadow_ray_shortening)});
  return d;
  // ASSIGNMENT a5.3 END
}

/// The emitter a hit lies on (found by its material: every emitter of the built-in scenes has
/// its own), or nothing.
inline const Emitter* emitter_at(const Scene& scene, const Hit& hit) {
  for (const Emitter& e : scene.emitters()) {
    const std::uint32_t m = e.kind == Emitter::quad ? scene.quads()[e.index].material()
                                                    : scene.spheres()[e.index].material;
    if (m == hit.material) return &e;
  }
  return nullptr;
}

/// p_w of the light sampler for the direction `ray` took to reach `hit` on an emitter, seen
/// from the ray's origin: (1/N) p_w(y) (r = hit.t, unit direction). What light sampling would
/// have given this direction, for the MIS weight of a BSDF-sampled hit.
inline double light_pdf_towards(const Scene& scene, const Ray& ray, const Hit& hit) {
  const Emitter* e = emitter_at(scene, hit);
  if (!e) return 0.0;
  const double n = static_cast<double>(scene.emitters().size());
  const double cos_y = glm::dot(hit.normal, -ray.direction);  // the hit's normal faces the ray
  return emitter_pdf_solid_angle(scene, *e, ray.origin, hit.point, hit.t, cos_y) / n;
}

}  // namespace mcrt
