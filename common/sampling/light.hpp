#pragma once
/// Samplers of points on lights, beside their pdfs per unit AREA, and the change of measure
/// that turns an area pdf into a pdf per steradian as seen from a shading point x:
///
///   dw = cos(theta_y) dA(y) / r^2,   so   p_w(w) = p_A(y) r^2 / cos(theta_y),
///
/// with y the sampled point, r = |y - x| and theta_y the angle between the light's normal at y
/// and the direction back to x. Pure functions of u in [0,1)^2, as every sampler here.
///
/// The sphere light is sampled BY AREA over the part of it that can be seen, a spherical cap.
/// Sampling by the solid angle of the cone the whole sphere subtends is the textbook choice for
/// a sphere floating in the open, but the one sphere light of the lecture (cornell-spheres) is
/// a 600-radius ball sunk into the ceiling with only a cap 0.27 deep showing: its cone fills
/// most of the upper hemisphere and almost all of it is ceiling. Uniform area on that cap puts
/// every sample on the visible light; for a whole sphere (the furnace: the cap is everything)
/// it is uniform area on the sphere.

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
  const double z = 1.0 - (height / radius) * u.x;
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Vec2 circle = cos_sin_two_pi(u.y);  // (cos phi, sin phi) at phi = 2 pi u1
  const Vec3 n = Frame(axis).to_world({s * circle.x, s * circle.y, z});
  return {centre + radius * n, n, 1.0 / (k_two_pi * radius * height)};
}
inline double sphere_cap_pdf_area(double radius, double height) {
  return 1.0 / (k_two_pi * radius * height);
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
