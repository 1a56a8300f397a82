#pragma once
// Chapter 08's plan: the references a run compares with and the work it is expected to do,
// known from the flags (what it refuses is checked in main.cpp's run).

#include <algorithm>
#include <string>

#include "app/ray_limit.hpp"
#include "app/reference_cache.hpp"
#include "render/russian_roulette.hpp"

#include "plates.hpp"

namespace mcrt {

inline constexpr double k_rays_per_sample =
    32.0;  // a generous mean for NEE and MIS paths (2 per vertex)

inline ReferenceSpec reference_spec(const auto& o, const std::string& scene, double light_scale) {
  ReferenceSpec spec;
  spec.scene = o.scene;
  spec.scene.scene = scene;
  spec.scene.params.light_scale = light_scale;
  spec.width = o.image.width;
  spec.height = o.image.height;
  spec.spp = o.reference_spp;
  spec.max_depth = o.depth;
  spec.seed = o.common.seed;
  spec.threads = o.common.threads;
  spec.quiet = o.common.quiet;
  return spec;
}

// Rays per sample in the furnace, whose paths end by roulette only: 2 per vertex of the length
// its albedo implies (min_depth + 1 / (1 - a)), where that is more than the generous mean.
inline double furnace_rays_per_sample(const auto& o) {
  return std::max(k_rays_per_sample,
                  2.0 * furnace_path_vertices(o.scene.params.furnace_albedo, Roulette{}.min_depth));
}

// The references (at most 6, one per scene of the shoot-out and the chosen one, if not cached),
// the two images at --spp, and the shoot-out: 6 estimators x 6 scenes, each up to its largest
// budget plus one pass (at most 65 rays a pixel: the depth-64 baselines; in the furnace, its
// paths' length if that is more).
inline RayWork predicted_work(const auto& o) {
  const double pixels = static_cast<double>(o.image.width) * o.image.height;
  const double furnace = furnace_rays_per_sample(o);
  const double references =
      5.0 * reference_predicted_rays(reference_spec(o, "cornell", 1.0), k_rays_per_sample) +
      reference_predicted_rays(reference_spec(o, "furnace", 1.0), furnace);
  const double chosen = o.scene.scene == "furnace" ? furnace : k_rays_per_sample;
  const double images = 2.0 * o.spp * pixels * chosen;
  const double shootout =
      (30.0 * (o.budgets.back() + 65.0) + 6.0 * (o.budgets.back() + std::max(65.0, furnace))) *
      pixels;
  const double plates = plates_predicted_rays(o.image.width, o.image.height, o.plates_spp);
  return {references + images + shootout + plates,
          "(6 references x reference spp + 2 x spp) x pixels x 32 rays (furnace: 2 (3 + 1 / "
          "(1 - albedo)) if more) + 36 x (largest --ray-budgets + 65) x pixels + 20 x "
          "--plates-spp x 2.25 pixels x 3 rays"};
}

}  // namespace mcrt
