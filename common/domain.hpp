#pragma once
/// Integration domains: an interval [lower, upper] on the line and an axis-aligned box in k
/// dimensions. The box keeps its corners in fixed-size arrays, so points in it live on the
/// stack and integrating over it allocates nothing.

#include <array>
#include <cstddef>
#include <span>

namespace mcrt {

/// The most dimensions a Box can have.
inline constexpr int k_max_box_dims = 16;

/// A point of a Box: the first `dims` entries are its coordinates.
using BoxPoint = std::array<double, k_max_box_dims>;

/// [lower, upper] on the real line.
struct Segment {
  double lower = 0.0;
  double upper = 1.0;
  double length() const { return upper - lower; }
};

/// [lower_0, upper_0] x ... x [lower_{k-1}, upper_{k-1}], k = dims <= k_max_box_dims.
struct Box {
  int dims = 1;
  BoxPoint lower{};
  BoxPoint upper{};

  /// The cube [lower, upper]^k.
  static Box cube(int k, double lower, double upper) {
    Box box;
    box.dims = k;
    for (int i = 0; i < k; ++i) {
      box.lower[i] = lower;
      box.upper[i] = upper;
    }
    return box;
  }

  /// vol = prod_i (upper_i - lower_i).
  double volume() const {
    double v = 1.0;
    for (int i = 0; i < dims; ++i) v *= upper[i] - lower[i];
    return v;
  }

  /// The first `dims` coordinates of `x`: what an integrand over this box is given.
  std::span<const double> coordinates(const BoxPoint& x) const {
    return {x.data(), static_cast<std::size_t>(dims)};
  }
};

}  // namespace mcrt
