#pragma once
// Chapter 05's flags: the images (--spp, --depth), the reference they are measured against, the
// shallow depths of the bias study, smallpt's scene beside it, and how the paths run (--engine,
// --sampler).

#include <filesystem>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/reference_cache.hpp"
#include "render/scene.hpp"
#include "sampling/path_sampler.hpp"

namespace mcrt::ch05 {

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{256, 192};
  std::vector<int> spp{1, 4, 16, 64, 256};  // samples per pixel of each image
  int depth = 10;                           // bounces after the camera ray's hit
  int reference_spp = 1024;                 // 0: no reference, no error against it
  std::vector<int> bias_depths{0, 1, 2};    // shallow depths rendered again against the reference
  int smallpt_spp = 64;                     // smallpt.png's spp (0: not rendered)
  bool lanes = true;                        // --engine lanes (true) or loop
  PathSampler sampler = PathSampler::independent;  // where each path's uniforms come from
  std::filesystem::path reference_dir;             // default: the user's cache folder
};

inline void add_options(CLI::App& app, Options& o) {
  add_render_options(app, o.scene, o.image, scene_names());  // veach-plates too: glossy lobes
  add_list_option(app, "--spp", o.spp, "Samples per pixel of each image (a list: 1,4,16)", 1,
                  1 << 16);
  add_number_option(app, "--depth", o.depth, "Bounces after the first hit (0: emitted light only)",
                    0, 1000);
  add_number_option(app, "--reference-spp", o.reference_spp,
                    "Samples per pixel of the reference image, without a depth cut (cached under "
                    "--reference-dir; 0: no reference)",
                    0, 1 << 20);
  add_choice_option(
      app, "--engine", {"lanes", "loop"}, "lanes",
      [&](const std::string& name) { o.lanes = name == "lanes"; },
      "How the path loop runs: lanes (four paths at a time) or loop (one at a time, the "
      "lecture's loop as written); the images are the same bit for bit");
  add_choice_option(
      app, "--sampler", {"independent", "jittered", "sobol"}, "independent",
      [&](const std::string& name) { o.sampler = *path_sampler_named(name); },
      "Where each path's uniforms come from: independent (a random stream per sample), "
      "jittered or sobol (each pixel's samples stratified in the pixel and at every bounce: "
      "padded 2D sets; rendered one path at a time, whatever --engine)");
  add_list_option(app, "--bias-depths", o.bias_depths,
                  "Depths rendered again at every --spp against the reference, for "
                  "rmse_vs_spp.png and depth_bias.csv: the error against the reference levels "
                  "off at their bias (a list: 0,1,2; only with a reference)",
                  0, 1000);
  add_number_option(app, "--smallpt-spp", o.smallpt_spp,
                    "Samples per pixel of smallpt.png: smallpt's mirror and glass scene at the "
                    "image size and --depth, to show what a mirror does to uniform sampling "
                    "(0: not rendered)",
                    0, 1 << 16);
  add_reference_dir_option(app, o.reference_dir);
}

}  // namespace mcrt::ch05
