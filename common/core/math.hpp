#pragma once
/// Vector aliases and constants shared by every chapter.
///
/// Double precision throughout: the sphere Cornell box has walls of radius 1e5, and float
/// round-off at that scale is not this lecture's subject.

#include <glm/glm.hpp>

namespace mcrt {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Color = glm::dvec3;  ///< linear RGB radiance or reflectance

inline constexpr double k_pi = 3.14159265358979323846;
inline constexpr double k_two_pi = 2.0 * k_pi;
inline constexpr double k_inv_pi = 1.0 / k_pi;
inline constexpr double k_inv_two_pi = 1.0 / k_two_pi;

/// Mean of the three channels: the scalar "brightness" used in summaries and error tables.
inline double average(const Color& c) { return (c.r + c.g + c.b) / 3.0; }

inline bool is_finite(const Color& c) {
  return glm::all(glm::lessThan(glm::abs(c), Color(1e300)));  // false for NaN and infinity
}

}  // namespace mcrt
