#pragma once
/// An orthonormal basis around a unit normal: local sample directions (normal = +z) to world.

#include <cmath>

#include "core/math.hpp"

namespace mcrt {

/// An orthonormal basis around a unit normal n (Duff et al. 2017, branchless).
struct Frame {
  Vec3 tangent, bitangent, normal;

  explicit Frame(const Vec3& n) : normal(n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    tangent = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
  }

  /// Local (x, y, z) with z along the normal -> world direction.
  Vec3 to_world(const Vec3& local) const {
    return local.x * tangent + local.y * bitangent + local.z * normal;
  }
};

}  // namespace mcrt
