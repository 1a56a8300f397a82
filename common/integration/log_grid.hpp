#pragma once
/// Sample counts for convergence studies: integers spaced evenly in log(N).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace mcrt {

/// Distinct integers from `first` to `last` (both included), `per_decade` per factor of 10,
/// evenly spaced in log N. Needs 1 <= first <= last.
inline std::vector<std::uint64_t> log_grid(std::uint64_t first, std::uint64_t last,
                                           int per_decade) {
  std::vector<std::uint64_t> grid;
  const double decades = std::log10(static_cast<double>(last) / static_cast<double>(first));
  const int steps = std::max(1, static_cast<int>(std::ceil(decades * per_decade)));
  for (int i = 0; i <= steps; ++i) {
    const double n = static_cast<double>(first) * std::pow(10.0, decades * i / steps);
    const auto value = std::clamp<std::uint64_t>(std::llround(n), first, last);
    if (grid.empty() || value > grid.back()) grid.push_back(value);
  }
  if (grid.back() != last) grid.push_back(last);
  return grid;
}

}  // namespace mcrt
