#pragma once
// Chapter 04's plan: every render of the run and its predicted rays, known and checked against
// --max-rays before any work is done.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/ray_limit.hpp"
#include "render/recursive_estimator.hpp"

namespace mcrt {

// Every render of the run and its predicted ray count (no escapes), known before any work.
struct Plan {
  std::uint64_t pixels = 0;
  int limit_depth = 0;
  std::vector<int> equal_cost_spp;  // per N: budget / rays per sample; 0 when one is over
  double predicted_rays = 0.0;      // a double: the request may exceed 2^64
};

// The limit is rendered at `limit_depth` or twice --max-depth, whichever is deeper; the
// missing-light renders take `light_spp` samples.
inline Plan make_plan(const auto& o, int limit_depth, int light_spp) {
  Plan plan;
  plan.pixels = static_cast<std::uint64_t>(o.image.width) * o.image.height;
  plan.limit_depth = std::max(limit_depth, 2 * o.max_depth);
  const auto rays = [&](int n, int k, int spp) {
    return static_cast<double>(plan.pixels) * spp * static_cast<double>(max_rays_per_sample(n, k));
  };
  for (int n : o.branching)
    for (int k = 0; k <= o.max_depth; ++k) plan.predicted_rays += rays(n, k, o.spp);
  // The missing-light renders and grid.png's top row, N = 1 at every k.
  for (int k = 0; k <= o.max_depth; ++k)
    plan.predicted_rays += rays(1, k, light_spp) + rays(1, k, o.grid_spp);
  plan.predicted_rays += rays(1, plan.limit_depth, light_spp);
  for (int n : o.branching) {
    const std::uint64_t per_sample = max_rays_per_sample(n, o.equal_cost_depth);
    const auto spp = static_cast<int>(static_cast<std::uint64_t>(o.budget) / per_sample);
    plan.equal_cost_spp.push_back(spp);
    plan.predicted_rays += 2.0 * rays(n, o.equal_cost_depth, spp);  // two independent renders
  }
  return plan;
}

// Refuses impossible work before any is done: exit code 2, naming the flag.
inline void check_plan(const auto& o, const Plan& plan) {
  const int cheapest = o.branching.front();  // sorted: the smallest N
  const std::uint64_t cheapest_sample = max_rays_per_sample(cheapest, o.equal_cost_depth);
  if (static_cast<std::uint64_t>(o.budget) < cheapest_sample)
    throw UsageError(
        fmt::format("--budget: {} rays per pixel cannot pay for one sample at "
                    "--equal-cost-depth {} (N = {} needs {}); give at least that",
                    o.budget, o.equal_cost_depth, cheapest, cheapest_sample));
  check_ray_limit({plan.predicted_rays, "sweep, missing-light and equal-cost renders"}, o.max_rays,
                  "--max-rays", o.common.threads,
                  "lower --max-depth, --branching, --spp, --budget or --grid-spp, or raise "
                  "--max-rays");
}

}  // namespace mcrt
