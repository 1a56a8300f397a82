#pragma once
// The render study's flags (--sampler, --render-*, --reference-dir) and what it refuses up front
// (an image too large, too many rays, a cache folder not of our own), kept out of main.cpp so
// that the chapter reads as the point-set studies it is about.

#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/ray_limit.hpp"
#include "app/reference_cache.hpp"
#include "app/usage_error.hpp"
#include "render_study.hpp"

namespace mcrt::ch09 {

inline void add_render_study_options(CLI::App& app, RenderStudyOptions& r, std::string& sampler) {
  add_choice_option(
      app, "--sampler", {"all", "independent", "jittered", "sobol"}, sampler,
      [&sampler](const std::string& name) { sampler = name; },
      "Samplers of the render study: all, or one of independent, jittered, sobol (jittered and "
      "sobol: each pixel's samples stratified, padded per bounce)");
  add_number_option(app, "--render-max-spp", r.max_spp,
                    "The render study: chapter 05's path tracer at spp = 1, 2, 4, ..., this (a "
                    "power of two; 0: no render study)",
                    0, 1 << 14);
  add_choice_option(
      app, "--render-scene", {"cornell", "cornell-spheres"}, r.scene.scene,
      [&r](const std::string& name) { r.scene.scene = name; }, "Scene of the render study");
  add_number_option(app, "--render-width", r.width, "Width of the render study's images", 1, 4096);
  add_number_option(app, "--render-height", r.height, "Height of the render study's images", 1,
                    4096);
  add_number_option(app, "--render-depth", r.full_depth,
                    "The render study's full depth (its other depth is 1: direct light)", 2, 1000);
  add_number_option(app, "--render-reference-spp", r.reference_spp,
                    "Samples per pixel of the render study's references (chapter 08's MIS, cached "
                    "under --reference-dir)",
                    2, 1 << 20);
  add_reference_dir_option(app, r.reference_dir);  // the study's references
}

// After parsing: the samplers chosen, and the study's refusals (UsageError naming the flags).
inline void check_render_study(RenderStudyOptions& r, const std::string& sampler,
                               const CommonOptions& common) {
  if (sampler != "all") r.samplers = {*path_sampler_named(sampler)};
  if (r.max_spp == 0) return;
  const auto max_spp = static_cast<std::uint32_t>(r.max_spp);
  if ((max_spp & (max_spp - 1)) != 0)
    throw UsageError(
        fmt::format("--render-max-spp {}: give 0 or a power of two up to {}", max_spp, 1 << 14));
  check_image_size({r.width, r.height});
  check_ray_limit(study_work(r), k_max_rays,
                  "--render-max-spp and --render-{width,height,depth,reference-spp}",
                  common.threads, "lower one of them");
  check_reference_folder(reference_folder(r.reference_dir), common.out);
}

}  // namespace mcrt::ch09
