#pragma once
/// Samplers of points on lights, beside their pdfs per unit AREA, and the change of measure
/// that turns an area pdf into a pdf per steradian as seen from a shading point x:
///
///   dw = cos(theta_y) dA(y) / r^2,   so   p_w(w) = p_A(y) r^2 / cos(theta_y),
///
/// with y the sampled point, r = |y - x| and theta_y the angle between the light's normal at y
/// and the direction back to x. Pure functions of u in [0,1)^2, as every sampler here.
///
/// A sphere light is sampled in one of three ways, chosen by where the shading point x is
/// (render/light_sampling.hpp decides, and says why each choice covers every point x can see):
///  - by AREA over a spherical cap, when only that cap can be seen from x (the one sphere light
///    of the lecture, cornell-spheres, is a 600-radius ball sunk into the ceiling with a cap
///    0.27 deep showing: from inside the room the cone of the whole sphere fills most of the
///    upper hemisphere and almost all of it is ceiling, while uniform area on the cap puts every
///    sample on the visible light);
///  - by SOLID ANGLE over the cone the whole sphere subtends, from a point outside it (the
///    textbook choice: every direction of the cone meets the sphere's near side);
///  - by AREA over the whole sphere, from a point inside it (the furnace, where it is exact).

#include <algorithm>
#include <cmath>

#include "core/cos_sin.hpp"
#include "core/math.hpp"
#include "sampling/frame.hpp"

namespace mcrt {

/// A point on a light, with the light's unit normal there (outward) and its pdf per unit area.
struct LightPoint {
  Vec3 point;
  Vec3 normal;
  double pdf_area = 0.0;
};

/// Uniform on the parallelogram corner + a edge_u + b edge_v, (a, b) = u: pdf = 1 / A, with
/// A = |edge_u x edge_v|; the normal is edge_u x edge_v normalised.
inline LightPoint sample_quad(const Vec3& corner, const Vec3& edge_u, const Vec3& edge_v, Vec2 u) {
  const Vec3 n = glm::cross(edge_u, edge_v);
  const double area = glm::length(n);
  return {corner + u.x * edge_u + u.y * edge_v, n / area, 1.0 / area};
}
inline double quad_pdf_area(double area) { return 1.0 / area; }

/// Uniform by area on the cap of height h of the sphere (centre c, radius R) around the unit
/// axis: the points with (p - c).axis / R = z in [1 - h/R, 1]. Archimedes: a zone's area
/// 2 pi R dz is linear in z, so z = 1 - (h/R) u0 and phi = 2 pi u1 give uniform area;
/// pdf = 1 / (2 pi R h). h = 2R is the whole sphere (pdf 1 / (4 pi R^2)).
inline LightPoint sample_sphere_cap(const Vec3& centre, double radius, const Vec3& axis,
                                    double height, Vec2 u) {
  // ASSIGNMENT a2.3 BEGIN withheld stub: (void)centre; (void)radius; (void)axis; (void)height; (void)u; NOT_IMPLEMENTED(sample_sphere_cap);
  const double z = 1.0 - (height / radius) * u.x;
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  const Vec3 n = Frame(axis).to_world({s * circle.x, s * circle.y, z});
  return {centre + radius * n, n, 1.0 / (k_two_pi * radius * height)};
  // ASSIGNMENT a2.3 END
}
inline double sphere_cap_pdf_area(double radius, double height) {
  return 1.0 / (k_two_pi * radius * height);
}

/// The cone of directions from x (outside the sphere) that meet the sphere: half-angle
/// theta_max with sin(theta_max) = R / d, d = |c - x|. Uniform in solid angle over it:
///   p_w = 1 / (2 pi (1 - cos(theta_max))),
// ASSIGNMENT a2.5 BEGIN withheld stub: /// drawn by inverting its cdf (a2.5's task: sampling/cone.hpp).
///   cos(theta) = 1 - u0 (1 - cos(theta_max)), phi = 2 pi u1 about the axis x -> c (the cap of
///   directions has area 2 pi (1 - cos), and that area is linear in cos(theta): Archimedes again).
// ASSIGNMENT a2.5 END
/// 1 - cos(theta_max) is written as (R/d)^2 / (1 + cos(theta_max)): for a large sphere close by
/// (cos near 0.1) either form is fine, for a small far one (cos near 1) this one keeps its digits.
inline double sphere_cone_one_minus_cos(const Vec3& centre, double radius, const Vec3& x) {
  const double d2 = glm::dot(centre - x, centre - x), sin2 = radius * radius / d2;
  return sin2 / (1.0 + std::sqrt(std::max(0.0, 1.0 - sin2)));
}
inline double sphere_cone_pdf_solid_angle(const Vec3& centre, double radius, const Vec3& x) {
  return 1.0 / (k_two_pi * sphere_cone_one_minus_cos(centre, radius, x));
}

/// A direction of the cone from x, and the point y where it first meets the sphere, with its
/// pdf moved to area measure (p_A = p_w cos(theta_y) / r^2) so that every light sampler hands
/// back the same record. x must lie outside the sphere.
inline LightPoint sample_sphere_cone(const Vec3& centre, double radius, const Vec3& x, Vec2 u) {
  const Vec3 axis = glm::normalize(centre - x);
  const double one_minus_cos_max = sphere_cone_one_minus_cos(centre, radius, x);
  // ASSIGNMENT a2.5 BEGIN withheld stub: (void)axis; (void)u; NOT_IMPLEMENTED(sample_sphere_cone); const Vec3 w(0.0);
  const double cos_theta = 1.0 - u.x * one_minus_cos_max;
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  const Vec2 circle = cos_sin_two_pi(u.y);
  const Vec3 w = Frame(axis).to_world({sin_theta * circle.x, sin_theta * circle.y, cos_theta});
  // ASSIGNMENT a2.5 END
  // The near root of |x + t w - c| = R (the far one is hidden behind it); at the cone's rim
  // the two meet and round-off can make the discriminant slightly negative.
  const Vec3 xc = centre - x;
  const double b = glm::dot(xc, w);
  const double t = b - std::sqrt(std::max(0.0, b * b - glm::dot(xc, xc) + radius * radius));
  const Vec3 y = x + t * w;
  const Vec3 n = (y - centre) / radius;
  const double cos_y = std::max(0.0, -glm::dot(n, w));
  return {y, n, cos_y / (t * t) / (k_two_pi * one_minus_cos_max)};
}

/// p_w = p_A r^2 / |cos(theta_y)|: the area pdf of a point at distance r, seen at angle
/// theta_y to its normal, per steradian at the shading point. 0 for a point seen edge-on
/// (cos = 0: the direction has no solid angle to give it).
inline double area_to_solid_angle_pdf(double pdf_area, double distance, double cos_light) {
  const double c = std::abs(cos_light);
  return c > 0.0 ? pdf_area * distance * distance / c : 0.0;
}

/// p_A = p_w |cos(theta_y)| / r^2: the inverse change of measure.
inline double solid_angle_to_area_pdf(double pdf_solid_angle, double distance, double cos_light) {
  return pdf_solid_angle * std::abs(cos_light) / (distance * distance);
}

}  // namespace mcrt
