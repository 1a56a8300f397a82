#pragma once
/// The trapezoid rule: integrate f by sampling it on a regular grid of n points per axis.
///
/// In 1D, with h = (b - a)/(n - 1) and x_i = a + i h,
///   T_n = h [ f(x_0)/2 + f(x_1) + ... + f(x_{n-2}) + f(x_{n-1})/2 ],
///   I - T_n = -(b - a) h^2 f''(xi) / 12   for f in C^2:  O(n^-2),
/// and O(n^-1) when f jumps (the cell holding the jump is off by up to h times the jump).
/// In k dimensions the tensor-product rule applies the 1D rule along every axis,
///   T = sum_{i_1..i_k} w_{i_1} ... w_{i_k} f(x_{i_1}, ..., x_{i_k}),  w_i = h or h/2 at the ends,
/// which costs N = n^k evaluations for the same O(h^2) = O(N^(-2/k)) error.
///
/// The integrand is any callable, inlined into the loop: f(double) on a Segment,
/// f(std::span<const double>) on a Box. Nothing is allocated.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "integration/compensated_sum.hpp"
#include "integration/domain.hpp"

namespace mcrt {

/// The i-th of n evenly spaced points from lower to upper (n >= 2), written so that the ends
/// are exact and a grid symmetric about 0 is exactly symmetric (points land on 0, +-1, ...
/// where they should, not an ulp beside them).
inline double grid_point(double lower, double upper, std::uint64_t i, std::uint64_t n) {
  const auto last = static_cast<double>(n - 1);
  const auto id = static_cast<double>(i);
  return (lower * (last - id) + upper * id) / last;
}

/// The trapezoid rule T_n on `segment` with n >= 2 points (n - 1 intervals).
template <class F>
double trapezoid(F&& f, const Segment& segment, std::uint64_t n) {
  // ASSIGNMENT a1.4 BEGIN stub: (void)f; (void)segment; (void)n; NOT_IMPLEMENTED(trapezoid on a Segment);
  const double h = segment.length() / static_cast<double>(n - 1);
  CompensatedSum sum;
  sum.add(0.5 * f(segment.lower));
  for (std::uint64_t i = 1; i + 1 < n; ++i)
    sum.add(f(grid_point(segment.lower, segment.upper, i, n)));
  sum.add(0.5 * f(segment.upper));
  return h * sum.value();
  // ASSIGNMENT a1.4 END
}

/// The tensor-product trapezoid rule on `box` with n >= 2 points per axis: n^dims evaluations.
/// Axis 0 is the inner loop; the others advance like an odometer.
template <class F>
double trapezoid(F&& f, const Box& box, std::uint64_t n) {
  // ASSIGNMENT a1.4 BEGIN withheld stub: (void)f; (void)box; (void)n; NOT_IMPLEMENTED(trapezoid on a Box);
  const int k = box.dims;
  BoxPoint h{};
  for (int axis = 0; axis < k; ++axis)
    h[axis] = (box.upper[axis] - box.lower[axis]) / static_cast<double>(n - 1);
  const auto end_weight = [n](std::uint64_t i) { return i == 0 || i + 1 == n ? 0.5 : 1.0; };

  std::array<std::uint64_t, k_max_box_dims> index{};
  BoxPoint outer = box.lower;  // the current line's coordinates on axes 1..k-1
  PointBatch batch;
  batch.dims = k;
  CompensatedSum total;
  while (true) {
    // One line along axis 0: h_0 sum_i w_i f(x_i, x_outer), its points written a batch at a
    // time, then evaluated (see PointBatch).
    CompensatedSum line;
    for (std::uint64_t first = 0; first < n; first += k_point_batch) {
      const auto count =
          static_cast<std::size_t>(std::min<std::uint64_t>(k_point_batch, n - first));
      for (std::size_t j = 0; j < count; ++j) {
        double* point = batch.point(j);
        point[0] = grid_point(box.lower[0], box.upper[0], first + j, n);
        for (int axis = 1; axis < k; ++axis) point[axis] = outer[axis];
      }
      for (std::size_t j = 0; j < count; ++j) line.add(end_weight(first + j) * f(batch[j]));
    }
    double outer_weight = h[0];
    for (int axis = 1; axis < k; ++axis) outer_weight *= end_weight(index[axis]) * h[axis];
    total.add(outer_weight * line.value());

    int axis = 1;  // odometer over axes 1..k-1
    for (; axis < k; ++axis) {
      if (++index[axis] < n) {
        outer[axis] = grid_point(box.lower[axis], box.upper[axis], index[axis], n);
        break;
      }
      index[axis] = 0;
      outer[axis] = box.lower[axis];
    }
    if (axis >= k) return total.value();
  }
  // ASSIGNMENT a1.4 END
}

/// n^dims, or 0 if it does not fit in 64 bits: the cost of a tensor-product grid.
inline std::uint64_t grid_evaluations(std::uint64_t n, int dims) {
  std::uint64_t total = 1;
  for (int i = 0; i < dims; ++i) {
    if (n != 0 && total > std::numeric_limits<std::uint64_t>::max() / n) return 0;
    total *= n;
  }
  return total;
}

/// The largest n with n^dims <= evaluations (at least 1; dims >= 1).
inline std::uint64_t points_per_axis_within(std::uint64_t evaluations, int dims) {
  const auto fits = [&](std::uint64_t n) {
    const std::uint64_t cost = grid_evaluations(n, dims);
    return cost != 0 && cost <= evaluations;
  };
  // The root in floating point, then corrected by a step or two for its round-off.
  auto n = static_cast<std::uint64_t>(std::pow(static_cast<double>(evaluations), 1.0 / dims));
  n = n < 1 ? 1 : n;
  while (n > 1 && !fits(n)) --n;
  while (fits(n + 1)) ++n;
  return n;
}

}  // namespace mcrt
