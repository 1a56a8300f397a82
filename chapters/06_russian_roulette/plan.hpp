#pragma once
// Chapter 06's plan: the work a run is expected to do, known from the flags, and what it
// refuses before starting (too many rays, too much memory, an infinite furnace).

#include <algorithm>

#include "app/cli.hpp"
#include "app/memory_limit.hpp"
#include "app/ray_limit.hpp"
#include "render/russian_roulette.hpp"

namespace mcrt {

// The survival per bounce assumed when predicting the throughput policy's rays outside the
// furnace (an expectation, not a bound: the Cornell boxes keep at most 0.73 per bounce).
inline constexpr double k_typical_survival = 0.8;

// Every q a flag takes: 0 would stop every path at once, 1 never (the furnace is closed).
inline constexpr double k_lowest_q = 0.001, k_highest_q = 0.999;

// The expected rays of a roulette path (d + 1/(1 - q)), at a survival of `q`.
inline double roulette_rays(int min_depth, double q) { return min_depth + 1.0 / (1.0 - q); }

// The rays the run is expected to trace: exact bounds for the depth cut, expectations for
// roulette (its paths have no longest length).
inline RayWork predicted_work(const auto& o) {
  const double a = o.scene.params.furnace_albedo;
  const double q_throughput = std::max(a, k_typical_survival);
  const double q_render = o.roulette.policy == RoulettePolicy::fixed ? o.roulette.q : q_throughput;
  const double pixels = static_cast<double>(o.image.width) * o.image.height;
  double rays = pixels * o.spp * (o.depth + 1.0 + roulette_rays(o.roulette.min_depth, q_render));
  double furnace = roulette_rays(o.roulette.min_depth, o.roulette.q);  // path lengths
  for (int k = 0; k <= o.depth; ++k) furnace += k + 1.0 + roulette_rays(k, q_render);
  for (double q : o.q) furnace += roulette_rays(o.roulette.min_depth, q);
  furnace += roulette_rays(o.roulette.min_depth, q_throughput);
  rays += furnace * o.paths;
  // splitting.csv: max(100, paths / n) paths per row, each 1 + n (d - 1 + 1/(1 - q)) rays.
  for (double q : o.split_q)
    for (int n : o.split_n)
      rays += std::max(100, o.paths / n) *
              (1.0 + n * roulette_rays(std::max(0, o.roulette.min_depth - 1), q));
  return {rays, "renders + furnace studies, expected rays for roulette"};
}

inline void check_request(const auto& o) {
  check_image_size(o.image);
  check_furnace_albedo(o.scene.params.furnace_albedo);
  check_ray_limit(predicted_work(o), k_max_rays,
                  "--paths, --q, --fixed-q, --split, --split-q, --spp, --depth", o.common.threads,
                  "lower one of them, or the image size");
  // At most 3 images at once (measured: 34 bytes per pixel at 1024x512).
  check_memory_limit(images_in_memory(static_cast<double>(o.image.width) * o.image.height, 3.0,
                                      o.common.threads, "3 images of --width x --height"),
                     "--width, --height", "lower them");
}

}  // namespace mcrt
