#pragma once
// Chapter 02's plan: the keys of its random streams and the columns of its tables, shared by
// the disk study (main.cpp) and the ball studies (ball_studies.hpp).

#include <cstdint>
#include <numeric>
#include <vector>

#include "io/table.hpp"

namespace mcrt::ch02 {

// Every estimate has its own random stream, keyed by (part, what it serves, trial), never by
// thread: the output does not depend on --threads.
enum Part : std::uint64_t { disk_error = 0, ball_table = 1, ball_error = 2, picture = 3 };
inline constexpr std::uint64_t k_parts = 256, k_indices = 1 << 24, k_trials = 1ull << 32;

inline Column real(const char* name) { return {name, Column::real, 10}; }
inline Column integer(const char* name) { return {name, Column::integer}; }

inline double sum(const std::vector<std::uint64_t>& grid) {
  return std::accumulate(grid.begin(), grid.end(), 0.0,
                         [](double s, std::uint64_t n) { return s + static_cast<double>(n); });
}

}  // namespace mcrt::ch02
