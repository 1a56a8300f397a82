#pragma once
/// Integration domains: an interval [lower, upper] on the line and an axis-aligned box in k
/// dimensions. The box keeps its corners in fixed-size arrays, and points in it live in
/// fixed-size batches on the stack, so integrating over it allocates nothing.

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
};

/// Points of a Box written in batches and only then evaluated. An integrand that reads its
/// point with wide (vector) loads right after the point was written coordinate by coordinate
/// makes the CPU wait for each store to reach the cache (store-to-load forwarding fails): a
/// measured 3x slowdown on e^(-|x|^2) in 4D. Writing a batch first lets the stores drain.
inline constexpr std::size_t k_point_batch = 64;

struct PointBatch {
  std::array<double, k_point_batch * k_max_box_dims> values{};
  int dims = 1;

  /// Point j's coordinates, to be written.
  double* point(std::size_t j) { return values.data() + j * static_cast<std::size_t>(dims); }
  /// Point j as an integrand is given it.
  std::span<const double> operator[](std::size_t j) const {
    return {values.data() + j * static_cast<std::size_t>(dims), static_cast<std::size_t>(dims)};
  }
};

}  // namespace mcrt
