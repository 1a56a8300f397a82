#pragma once
// Binnings for chi-square tests of samplers: a sampler's domain (square, disk, hemisphere)
// drawn as a rectangle of parameters (u, v) cut into a grid of cells. Each parameterisation
// has a constant Jacobian, measure = J du dv, so equal parameter cells are equal-area cells:
//   square      (x, y)              in [-1,1]^2,        dA = dx dy
//   disk        (r^2, phi)          in [0,1] x [0,2pi), dA = r dr dphi = 1/2 d(r^2) dphi
//   hemisphere  (phi, cos theta)    in [0,2pi) x [0,1], dw = sin(theta) dtheta dphi
//                                                          = dphi d(cos theta)

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/math.hpp"

namespace mcrt::testing {

/// A rectangle of parameters (u, v) cut into u_cells x v_cells equal cells; cell
/// (i, j) has index j * u_cells + i.
struct Grid {
  std::string name;     ///< e.g. "disk (r^2, phi)"
  std::string u_label;  ///< axis names, for reports
  std::string v_label;
  double u_min = 0.0, u_max = 1.0;
  double v_min = 0.0, v_max = 1.0;
  int u_cells = 1, v_cells = 1;
  double jacobian = 1.0;  ///< measure (area, solid angle) of the domain per unit (u, v) area

  int cell_count() const { return u_cells * v_cells; }
  double u_width() const { return (u_max - u_min) / u_cells; }
  double v_width() const { return (v_max - v_min) / v_cells; }
  double u_low(int i) const { return u_min + i * u_width(); }
  double v_low(int j) const { return v_min + j * v_width(); }
};

/// A grid over a domain of points of type Point (Vec2 or Vec3).
template <class Point>
struct Binning : Grid {
  /// The point at parameters (u, v).
  Point (*point_at)(double u, double v) = nullptr;
  /// The parameters of a point, or nothing when the point is not in the domain (off the disk,
  /// below the horizon, not unit length, NaN).
  std::optional<Vec2> (*parameters_of)(const Point& p) = nullptr;

  /// The cell index of a point, or -1 outside the domain.
  int cell_of(const Point& p) const {
    const std::optional<Vec2> uv = parameters_of(p);
    if (!uv) return -1;
    const int i = std::clamp(static_cast<int>((uv->x - u_min) / u_width()), 0, u_cells - 1);
    const int j = std::clamp(static_cast<int>((uv->y - v_min) / v_width()), 0, v_cells - 1);
    return j * u_cells + i;
  }
};

namespace detail {

// Round-off allowance for "on the domain": samplers compute r, cos and sin in double, so a
// point on the boundary may stray by a few ulps; 1e-9 is far above that and far below a cell.
inline constexpr double k_domain_slack = 1e-9;

inline double wrap_angle(double phi) { return phi < 0.0 ? phi + k_two_pi : phi; }

inline Vec2 square_point(double x, double y) { return {x, y}; }
inline std::optional<Vec2> square_parameters(const Vec2& p) {
  if (!(std::abs(p.x) <= 1.0 + k_domain_slack && std::abs(p.y) <= 1.0 + k_domain_slack))
    return std::nullopt;  // also rejects NaN
  return p;
}

inline Vec2 disk_point(double r2, double phi) {
  const double r = std::sqrt(r2);
  return {r * std::cos(phi), r * std::sin(phi)};
}
inline std::optional<Vec2> disk_parameters(const Vec2& p) {
  const double r2 = p.x * p.x + p.y * p.y;
  if (!(r2 <= 1.0 + k_domain_slack)) return std::nullopt;
  return Vec2(r2, wrap_angle(std::atan2(p.y, p.x)));
}

inline Vec3 hemisphere_point(double phi, double cos_theta) {
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta};
}
inline std::optional<Vec2> hemisphere_parameters(const Vec3& w) {
  const double length = glm::length(w);
  if (!(std::abs(length - 1.0) <= k_domain_slack && w.z >= -k_domain_slack)) return std::nullopt;
  return Vec2(wrap_angle(std::atan2(w.y, w.x)), w.z);
}
inline std::optional<Vec2> sphere_parameters(const Vec3& w) {
  const double length = glm::length(w);
  if (!(std::abs(length - 1.0) <= k_domain_slack)) return std::nullopt;
  return Vec2(wrap_angle(std::atan2(w.y, w.x)), w.z);
}

}  // namespace detail

/// The square [-1,1]^2 on an n x n grid.
inline Binning<Vec2> square_binning(int n) {
  return {{"square (x, y)", "x", "y", -1.0, 1.0, -1.0, 1.0, n, n, 1.0},
          &detail::square_point,
          &detail::square_parameters};
}

/// The unit disk on (r^2, phi) cells: equal areas, r^2_cells rings by phi_cells sectors.
inline Binning<Vec2> disk_binning(int r2_cells, int phi_cells) {
  return {{"disk (r^2, phi)", "r^2", "phi (rad)", 0.0, 1.0, 0.0, k_two_pi, r2_cells, phi_cells,
           0.5},
          &detail::disk_point,
          &detail::disk_parameters};
}

/// The hemisphere z >= 0 on (phi, cos theta) cells: equal solid angles. Use odd counts: an
/// error in the density like cos(m phi) integrates to zero in every cell, and is invisible,
/// exactly when m is a multiple of the cell count; samplers are built from quadrants and
/// octants (errors with m = 4, 8, 12, ...), and an odd count n makes the first invisible such
/// m = 4n rather than n itself.
inline Binning<Vec3> hemisphere_binning(int phi_cells, int cos_theta_cells) {
  return {{"hemisphere (phi, cos theta)", "phi (rad)", "cos(theta)", 0.0, k_two_pi, 0.0, 1.0,
           phi_cells, cos_theta_cells, 1.0},
          &detail::hemisphere_point,
          &detail::hemisphere_parameters};
}

/// The whole sphere on (phi, z) cells: equal solid angles (Archimedes), odd counts as above.
inline Binning<Vec3> sphere_binning(int phi_cells, int z_cells) {
  return {{"sphere (phi, z)", "phi (rad)", "z", 0.0, k_two_pi, -1.0, 1.0, phi_cells, z_cells, 1.0},
          &detail::hemisphere_point,  // (sin theta cos phi, sin theta sin phi, z) for any z
          &detail::sphere_parameters};
}

}  // namespace mcrt::testing
