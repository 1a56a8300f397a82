#pragma once
// Chapter 03's studies: which integrands at which k, the trapezoid grids n and Monte Carlo
// sizes N of each, as tasks, and the checks that refuse a plan before any work.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "integration/integrands.hpp"
#include "integration/log_grid.hpp"
#include "app/cli.hpp"

namespace mcrt {

constexpr int k_disk_dims = 2;                    // the lecture's disk, always studied
constexpr int k_per_decade = 5;                   // grid points per factor of 10 in N or n
constexpr double k_max_total_evaluations = 2e11;  // about 20 minutes on 2 cores

enum class Kind { gaussian_1d, ceil_sin_1d, gaussian_kd, unit_ball_kd };

struct Study {
  Kind kind;
  int dims;
  std::string name() const {
    const char* names[] = {"gaussian_1d", "ceil_sin_1d", "gaussian_kd", "unit_ball_kd"};
    return names[static_cast<int>(kind)];
  }
  bool smooth() const { return kind == Kind::gaussian_1d || kind == Kind::gaussian_kd; }
  // The slope of log(error) against log(N) the simple statement predicts.
  double theory_slope(bool trapezoid) const {
    return trapezoid ? (smooth() ? -2.0 : -1.0) / dims : -0.5;
  }
};

// Calls visit(f, domain) with the study's integrand as its own type, so every loop over
// samples is compiled for one integrand and inlined.
template <class Visit>
auto with_integrand(const Study& study, Visit&& visit) {
  switch (study.kind) {
    case Kind::gaussian_1d: {
      const Gaussian1D f;
      return visit(f, f.domain);
    }
    case Kind::ceil_sin_1d: {
      const CeilSinSquare1D f;
      return visit(f, f.domain);
    }
    case Kind::gaussian_kd: {
      const GaussianProduct f{study.dims};
      return visit(f, f.domain());
    }
    case Kind::unit_ball_kd:
    default: {
      const UnitBallIndicator f{study.dims};
      return visit(f, f.domain());
    }
  }
}

inline double reference(const Study& study) {
  return with_integrand(study, [](const auto& f, const auto&) { return f.reference(); });
}

// One point of a study: a trapezoid grid of n points per axis, or trials x F_N at N = n.
struct Task {
  std::size_t study, index;  // index: which n (trapezoid) or N (Monte Carlo) of the study
  bool trapezoid;
  std::uint64_t n;
  std::uint64_t evaluations;  // n^k, or trials * N
};

struct Plan {
  std::vector<Study> studies;
  std::vector<Task> tasks;            // per study its grids n, then its N
  std::vector<std::size_t> schedule;  // task indices, largest first: the cores finish together
  double total_evaluations = 0.0;
};

// The 1D integrands; e^{-|x|^2} at each k of `dims` (sorted); the ball at k = 2 (the disk)
// and at every k >= 2 of `dims` (at k = 1 it is all of [-1, 1]).
inline std::vector<Study> studies_for(const std::vector<int>& dims) {
  std::vector<Study> studies = {{Kind::gaussian_1d, 1}, {Kind::ceil_sin_1d, 1}};
  for (int k : dims) studies.push_back({Kind::gaussian_kd, k});
  if (!std::binary_search(dims.begin(), dims.end(), k_disk_dims))
    studies.push_back({Kind::unit_ball_kd, k_disk_dims});
  for (int k : dims)
    if (k >= 2) studies.push_back({Kind::unit_ball_kd, k});
  return studies;
}

// Throws UsageError unless the largest k has two grids (n = 2 and 3 points per axis) within
// the budget: a slope needs two points.
inline void check_grids(const std::vector<int>& dims, std::uint64_t max_evaluations) {
  const int largest = std::max(dims.back(), k_disk_dims);
  const std::uint64_t smallest_grid = grid_evaluations(3, largest);
  if (smallest_grid > max_evaluations)
    throw UsageError(
        fmt::format("--max-evaluations {} is below the smallest trapezoid study at "
                    "--dims {}: n = 2 and 3 points per axis need 3^{} = {} "
                    "evaluations; raise --max-evaluations or lower --dims",
                    max_evaluations, largest, largest, smallest_grid));
}

inline Plan make_plan(const std::vector<int>& dims, std::uint64_t max_evaluations, int trials) {
  check_grids(dims, max_evaluations);
  Plan plan;
  plan.studies = studies_for(dims);
  const std::vector<std::uint64_t> samples =
      log_grid(std::min<std::uint64_t>(10, max_evaluations), max_evaluations, k_per_decade);
  for (std::size_t s = 0; s < plan.studies.size(); ++s) {
    const int k = plan.studies[s].dims;
    const auto grid = log_grid(2, points_per_axis_within(max_evaluations, k), k_per_decade);
    for (std::size_t i = 0; i < grid.size(); ++i)
      plan.tasks.push_back({s, i, true, grid[i], grid_evaluations(grid[i], k)});
    for (std::size_t i = 0; i < samples.size(); ++i)
      plan.tasks.push_back(
          {s, i, false, samples[i], static_cast<std::uint64_t>(trials) * samples[i]});
  }
  for (const Task& task : plan.tasks)
    plan.total_evaluations += static_cast<double>(task.evaluations);
  if (plan.total_evaluations > k_max_total_evaluations)  // far too much work: refused at once
    throw UsageError(
        fmt::format("--trials {} with --max-evaluations {} and {} --dims: {:.3g} "
                    "evaluations in all, above the limit of {:.3g}; lower one of them",
                    trials, max_evaluations, dims.size(), plan.total_evaluations,
                    k_max_total_evaluations));
  for (std::size_t i = 0; i < plan.tasks.size(); ++i) plan.schedule.push_back(i);
  std::stable_sort(plan.schedule.begin(), plan.schedule.end(), [&](std::size_t a, std::size_t b) {
    return plan.tasks[a].evaluations > plan.tasks[b].evaluations;
  });
  return plan;
}

}  // namespace mcrt
