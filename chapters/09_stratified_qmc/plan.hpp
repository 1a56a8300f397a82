#pragma once
// Chapter 09's plan: the three studies as series (one sampler of one study at its sizes N),
// the tasks (one randomisation of one series at one N), the key of each task's points, and
// the check that refuses a plan too large before any work.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "integration/integrands.hpp"
#include "app/memory_limit.hpp"
#include "app/work_limit.hpp"
#include "sampling/point_random.hpp"
#include "samplers.hpp"

namespace mcrt::ch09 {

// The disk of chapter 02, a smooth 2D integrand (e^{-|x|^2} on [0,1]^2, chapter 03's), and
// chapter 03's e^{-|x|^2} on [0,1]^k at one budget for every k.
enum class Study { disk, smooth, dimension };

inline std::string name_of(Study study) {
  const char* names[] = {"disk", "smooth", "dimension"};
  return names[static_cast<int>(study)];
}

// Calls visit(f, box) with the study's integrand in `dims` dimensions, as its own type.
template <class Visit>
auto with_integrand(Study study, int dims, Visit&& visit) {
  if (study == Study::disk) {
    const UnitBallIndicator f{2};
    return visit(f, f.domain());
  }
  const GaussianProduct f{dims};
  return visit(f, f.domain());
}

// I and sigma^2 = vol J - I^2, the variance of vol f(X) for X uniform: V[F_N] = sigma^2 / N.
struct Moments {
  double integral, variance;
};
inline Moments moments_of(Study study, int dims) {
  return with_integrand(study, dims, [](const auto& f, const auto& box) {
    const double i = f.reference();
    return Moments{i, box.volume() * f.integral_of_square() - i * i};
  });
}

// One sampler of one study at its sizes N.
struct Series {
  Study study;
  Sampler sampler;
  int dims;
  bool power_of_two;  // every N a power of two (false: odd N between them)
  std::vector<std::uint32_t> sizes;
  std::string label() const { return name_of(sampler) + (power_of_two ? "" : "_odd_n"); }
  double predicted_slope() const {
    return study == Study::disk ? disk_predicted_slope(sampler)
                                : smooth_predicted_slope(sampler, power_of_two);
  }
};

// One randomisation (trial) of one series at its size_index-th N.
struct Task {
  std::size_t series, size_index;
  std::uint32_t trial, n;
};

struct Plan {
  std::vector<Series> series;
  std::vector<Task> tasks;            // per series, per N, per trial
  std::vector<std::size_t> schedule;  // task indices, largest first: the cores finish together
  double points = 0.0;                // every task's N, summed
  double coordinates = 0.0;
};

// The dimension study's point sets: random, Latin hypercube and scrambled Sobol'.
inline constexpr Sampler k_dimension_samplers[] = {Sampler::independent, Sampler::latin_hypercube,
                                                   Sampler::sobol_owen};
inline constexpr double k_max_coordinates = 7e10;  // about 20 minutes on 2 cores (6e7 a second)

// 16, 32, ..., max_n (a power of two).
inline std::vector<std::uint32_t> powers_of_two(std::uint32_t max_n) {
  std::vector<std::uint32_t> sizes;
  for (std::uint32_t n = 16; n <= max_n; n *= 2) sizes.push_back(n);
  return sizes;
}

// Odd N halfway (in log N) between the powers of two: round(2^(m + 1/2)) made odd, below max_n.
inline std::vector<std::uint32_t> odd_sizes(std::uint32_t max_n) {
  std::vector<std::uint32_t> sizes;
  for (std::uint32_t n = 16; 2 * n <= max_n; n *= 2)
    sizes.push_back(static_cast<std::uint32_t>(std::lround(n * std::sqrt(2.0))) | 1u);
  return sizes;
}

// The key of a task's points: the seed hashed with (study, series, size, trial), never a
// thread, so the points and the estimates do not depend on --threads.
inline std::uint64_t points_key(std::uint64_t seed, const Plan& plan, const Task& task) {
  return hash_bits(seed,
                   static_cast<std::uint64_t>(plan.series[task.series].study) << 56 |
                       task.series << 40 | task.size_index << 32,
                   task.trial);
}

inline Plan make_plan(std::uint32_t max_n, std::uint32_t budget, const std::vector<int>& dims,
                      int trials, int threads) {
  Plan plan;
  for (Study study : {Study::disk, Study::smooth})
    for (Sampler sampler : k_samplers)
      plan.series.push_back({study, sampler, 2, true, powers_of_two(max_n)});
  plan.series.push_back({Study::smooth, Sampler::sobol_owen, 2, false, odd_sizes(max_n)});
  for (Sampler sampler : k_dimension_samplers)  // by sampler, then k: each a line of the plot
    for (int k : dims) plan.series.push_back({Study::dimension, sampler, k, true, {budget}});
  for (const Series& series : plan.series)  // the work first: refused before any task is made
    for (std::uint32_t n : series.sizes) {
      plan.points += static_cast<double>(trials) * n;
      plan.coordinates += static_cast<double>(trials) * n * series.dims;
    }
  check_work_limit({plan.coordinates, "coordinates", "--trials x N x k over the three studies"},
                   k_max_coordinates, "--max-n, --budget, --dims and --trials",
                   "lower one of them");
  // The memory: the program and its threads, and per task its Task, its place in the
  // schedule and its estimate (the tables hold a row per series and N, far fewer).
  double tasks = 0.0;
  for (const Series& series : plan.series)
    tasks += static_cast<double>(trials) * static_cast<double>(series.sizes.size());
  MemoryUse use =
      images_in_memory(0.0, 0.0, threads, "the program, its threads and 40 bytes a task");
  use.bytes += tasks * (sizeof(Task) + sizeof(std::size_t) + sizeof(double));
  check_memory_limit(use, "--trials, --dims and --max-n", "lower one of them");
  for (std::size_t s = 0; s < plan.series.size(); ++s)
    for (std::size_t i = 0; i < plan.series[s].sizes.size(); ++i)
      for (int t = 0; t < trials; ++t)
        plan.tasks.push_back({s, i, static_cast<std::uint32_t>(t), plan.series[s].sizes[i]});
  const auto cost = [&](std::size_t i) {
    return std::uint64_t{plan.tasks[i].n} * plan.series[plan.tasks[i].series].dims;
  };
  for (std::size_t i = 0; i < plan.tasks.size(); ++i) plan.schedule.push_back(i);
  std::stable_sort(plan.schedule.begin(), plan.schedule.end(),
                   [&](std::size_t a, std::size_t b) { return cost(a) > cost(b); });
  return plan;
}

}  // namespace mcrt::ch09
