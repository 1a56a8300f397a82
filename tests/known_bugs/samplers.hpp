#pragma once
// Known-wrong samplers and pdfs, kept so the tests can show the chi-square sampler test
// (stats/sampler_tests.hpp) rejects them (tests/known_bugs_test.cpp).

#include <cmath>

#include "core/math.hpp"

namespace mcrt::testing {

/// Wrong: r = u instead of sqrt(u), so points crowd the disk's centre.
inline Vec2 disk_with_radius_u(Vec2 u) {
  const double r = u.x;
  const double phi = k_two_pi * u.y;
  return {r * std::cos(phi), r * std::sin(phi)};
}

/// Wrong: the uniform hemisphere's pdf given as 1/pi instead of 1/(2 pi) per steradian.
inline double hemisphere_pdf_one_over_pi(const Vec3&) { return k_inv_pi; }

/// Wrong: the cosine-weighted pdf with an extra factor 2, 2 cos(theta) / pi.
inline double cosine_pdf_times_two(const Vec3& w) { return 2.0 * w.z * k_inv_pi; }

}  // namespace mcrt::testing
