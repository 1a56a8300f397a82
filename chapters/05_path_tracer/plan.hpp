#pragma once
// Chapter 05's plan: the reference a run compares with, and the work it refuses before
// starting (too many rays, too much memory, an infinite furnace), all known from the flags.

#include <algorithm>
#include <filesystem>

#include "app/cli.hpp"
#include "app/memory_limit.hpp"
#include "app/ray_limit.hpp"
#include "app/reference_cache.hpp"
#include "render/russian_roulette.hpp"

namespace mcrt {

// A generous mean of rays per sample of the reference's estimator (MIS: 2 per vertex); in the
// furnace, 2 per vertex of the path length its albedo implies, if that is more.
inline constexpr double k_reference_rays_per_sample = 32.0;
inline double reference_rays_per_sample(const auto& o) {
  if (o.scene.scene != "furnace") return k_reference_rays_per_sample;
  return std::max(k_reference_rays_per_sample,
                  2.0 * furnace_path_vertices(o.scene.params.furnace_albedo, Roulette{}.min_depth));
}

// The reference: the same scene and size, no depth cut, its own sample streams.
inline ReferenceSpec reference_spec(const auto& o) {
  ReferenceSpec spec;
  spec.scene = o.scene;
  spec.width = o.image.width;
  spec.height = o.image.height;
  spec.spp = o.reference_spp;
  spec.max_depth = -1;
  spec.seed = o.common.seed;
  spec.threads = o.common.threads;
  spec.quiet = o.common.quiet;
  return spec;
}

// The reference cache: --reference-dir, else the user's cache folder (app/reference_cache.hpp).
inline std::filesystem::path reference_dir(const auto& o) {
  return reference_folder(o.reference_dir);
}

// The most rays the run can trace: two renders per spp, at most depth + 1 rays per sample,
// smallpt.png's one render, and the reference if it is not cached.
inline RayWork predicted_work(const auto& o) {
  double samples = 0.0;
  for (int spp : o.spp) samples += 2.0 * spp;
  const double smallpt =
      static_cast<double>(o.smallpt_spp) * o.image.width * o.image.height * (o.depth + 1.0);
  double study_depths = 0.0;  // the bias study's rays per sample, summed over its depths
  if (o.reference_spp > 0)
    for (int depth : o.bias_depths) study_depths += depth + 1.0;
  const double reference =
      o.reference_spp > 0
          ? reference_predicted_rays(reference_spec(o), reference_rays_per_sample(o))
          : 0.0;
  return {samples * o.image.width * o.image.height * (o.depth + 1.0 + study_depths) + smallpt +
              reference,
          "2 renders x sum of spp x pixels x (depth + 1 + sum of (bias depth + 1)) + smallpt spp "
          "x pixels x (depth + 1) + reference spp x pixels x 32 (furnace: 2 (3 + 1 / (1 - "
          "albedo)) if more)"};
}

// Throws UsageError (exit 2, naming the flags) for a run that cannot or should not be done.
inline void refuse_impossible_work(const auto& o) {
  check_image_size(o.image);
  // The furnace's reference has no depth cut: at albedo 1 its paths never end.
  if (o.scene.scene == "furnace") check_furnace_albedo(o.scene.params.furnace_albedo);
  check_ray_limit(predicted_work(o), k_max_rays,
                  "--spp, --depth, --width, --height, --reference-spp, --smallpt-spp, --albedo",
                  o.common.threads, "lower one of them");
  // A pair of renders, the reference's three and one kept per spp for the noise strip (measured:
  // 134 bytes per pixel at --spp 1,2,4, counted 240).
  check_memory_limit(images_in_memory(static_cast<double>(o.image.width) * o.image.height,
                                      7.0 + static_cast<double>(o.spp.size()), o.common.threads,
                                      "7 + spp values images"),
                     "--width, --height, --spp", "lower them");
  // Last: it makes the cache folder if it is missing.
  if (o.reference_spp > 0) check_reference_folder(reference_dir(o), o.common.out);
}

}  // namespace mcrt
