#pragma once
// Chapter 09's render study (--render-max-spp): chapter 05's path tracer with each --sampler,
// its RMS error against a converged reference at spp = 1, 2, 4, ..., max, at depth 1 (direct
// light) and at the full depth; the fitted slopes, the plot, and the 4-spp images side by side.
//
// Equal spp is equal rays here: every sampler traces the same estimator, one camera ray and at
// most depth further rays per sample; only where the uniforms come from differs (the rays
// column counts them).
//
// The reference R (chapter 08's MIS, cached, with the same depth cut, so no bias) has its own
// noise: E[(A - R)^2] = Var[A] + Var[R] per pixel. Its mean Var[R] is known (the reference's
// standard_error_rms^2), so rmse = sqrt(rmse_vs_reference^2 - se_R^2) estimates A's own error;
// the fit keeps only the rows where se_R^2 is at most half of rmse_vs_reference^2, so that the
// subtraction does not decide the slope.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/ray_limit.hpp"
#include "app/reference_cache.hpp"
#include "engine/path_tracer_lanes.hpp"
#include "integration/convergence.hpp"
#include "io/contact_sheet.hpp"
#include "io/image_file.hpp"
#include "io/plot.hpp"
#include "io/table.hpp"
#include "render/relative_error.hpp"
#include "render/scene.hpp"
#include "sampling/path_sampler.hpp"

namespace mcrt::ch09 {

struct RenderStudyOptions {
  std::vector<PathSampler> samplers = {PathSampler::independent, PathSampler::jittered,
                                       PathSampler::sobol};
  SceneOptions scene;        // --render-scene: cornell
  int width = 32;            // --render-width: pixels of each render
  int height = 24;           // --render-height
  int max_spp = 0;           // --render-max-spp: 0 no study, else spp = 1, 2, 4, ..., max_spp
  int full_depth = 10;       // --render-depth: the full depth (the other is 1, direct light)
  int reference_spp = 8192;  // --render-reference-spp
  std::filesystem::path reference_dir;  // --reference-dir (default: the user's cache folder)
};

// The two depths: direct light only, and the full path.
inline std::vector<int> study_depths(const RenderStudyOptions& o) { return {1, o.full_depth}; }

inline std::vector<int> study_spp(const RenderStudyOptions& o) {
  std::vector<int> spp;
  for (int n = 1; n <= o.max_spp; n *= 2) spp.push_back(n);
  return spp;
}

inline ReferenceSpec study_reference_spec(const RenderStudyOptions& o, int depth,
                                          std::uint64_t seed, int threads, bool quiet) {
  ReferenceSpec spec;
  spec.scene = o.scene;
  spec.width = o.width;
  spec.height = o.height;
  spec.spp = o.reference_spp;
  spec.max_depth = depth;  // the same cut as the renders: A and R estimate the same image
  spec.seed = seed;
  spec.threads = threads;
  spec.quiet = quiet;
  return spec;
}

// A generous mean of the reference's rays per sample (MIS: 2 per vertex), as chapter 05's.
inline constexpr double k_study_reference_rays_per_sample = 32.0;

// The most rays the study traces: per sampler and depth, sum of spp x pixels x (depth + 1),
// and the two references if they are not cached.
inline RayWork study_work(const RenderStudyOptions& o) {
  double rays = 0.0;
  if (o.max_spp == 0) return {0.0, ""};
  double spp = 0.0;
  for (int n : study_spp(o)) spp += n;
  for (int depth : study_depths(o)) {
    rays += static_cast<double>(o.samplers.size()) * spp * o.width * o.height * (depth + 1.0);
    rays += reference_predicted_rays(study_reference_spec(o, depth, 1, 1, true),
                                     k_study_reference_rays_per_sample);
  }
  return {rays,
          "samplers x sum of spp x pixels x (depth + 1) over depths 1 and --render-depth + 2 "
          "references x pixels x reference spp x 32"};
}

inline Table render_error_table() {
  return Table({{"sampler", Column::text},
                {"depth", Column::integer},
                {"spp", Column::integer},
                {"rays", Column::integer},
                {"rmse_vs_reference", Column::real, 6, Column::scientific},
                {"reference_standard_error", Column::real, 6, Column::scientific},
                {"rmse", Column::real, 6, Column::scientific},
                {"fitted", Column::integer}});
}

inline Table render_slopes_table() {
  return Table({{"sampler", Column::text},
                {"depth", Column::integer},
                {"fitted_slope", Column::real, 4, Column::fixed},
                {"standard_error", Column::real, 4, Column::fixed},
                {"points", Column::integer}});
}

struct RenderStudy {
  Table errors = render_error_table(), slopes = render_slopes_table();
  std::vector<Image> four_spp;  // the full depth at 4 spp, one per sampler (if max_spp >= 4)
  std::uint64_t rays = 0;
};

// A's own rms error: the reference's variance taken out of the mean squared error.
inline double own_rms_error(double rmse_vs_reference, double reference_standard_error) {
  return std::sqrt(std::max(0.0, rmse_vs_reference * rmse_vs_reference -
                                     reference_standard_error * reference_standard_error));
}

inline RenderStudy run_render_study(const RenderStudyOptions& o, std::uint64_t seed, int threads,
                                    bool quiet) {
  RenderStudy study;
  if (o.max_spp == 0) return study;
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.width, o.height);
  for (int depth : study_depths(o)) {
    const Reference reference =
        load_or_render_reference(reference_folder(o.reference_dir),
                                 study_reference_spec(o, depth, seed, threads, quiet));
    const double se = reference.info.value("standard_error_rms", 0.0);
    for (PathSampler sampler : o.samplers) {
      std::vector<double> fit_spp, fit_rmse;
      for (int spp : study_spp(o)) {
        const RenderSettings settings{spp, 0, seed, threads, nullptr};
        // render_sampled's image with estimate_path_radiance, four paths at a time
        const RenderResult a = render_path_tracer_lanes(scene, camera, settings, depth, sampler);
        const double raw = rms_error(a.image, reference.image);
        const bool fitted = se * se <= 0.5 * raw * raw;
        study.errors.add_row({name_of(sampler), depth, spp, a.rays, raw, se, own_rms_error(raw, se),
                              fitted ? 1 : 0});
        if (fitted) {
          fit_spp.push_back(spp);
          fit_rmse.push_back(own_rms_error(raw, se));
        }
        study.rays += a.rays;
        if (depth == o.full_depth && spp == 4) study.four_spp.push_back(a.image);
      }
      const ErrorSlope slope = fit_error_slope(fit_spp, fit_rmse, -0.5);
      study.slopes.add_row(
          {name_of(sampler), depth, slope.fit.slope, slope.fit.slope_standard_error, slope.points});
    }
  }
  return study;
}

// rms error against spp, one line per sampler and depth (solid: depth 1, dashed: full).
inline Plot render_error_plot(const RenderStudyOptions& o, const Table& slopes) {
  Plot plot;
  plot.name = "render_error_vs_spp";
  plot.title = fmt::format("{} {}x{}: rms error against spp (equal spp, equal rays)", o.scene.scene,
                           o.width, o.height);
  plot.x_label = "samples per pixel";
  plot.y_label = "rms error against the reference";
  plot.log_x = plot.log_y = true;
  plot.width = 1000;
  plot.height = 700;
  plot.settings = "set key outside right top\nset autoscale xfix\n";
  plot.plot = "plot ";
  const auto colour = [](const std::string& s) {
    return s == "independent" ? "#d62728" : s == "jittered" ? "#1f77b4" : "#2ca02c";
  };
  for (std::size_t r = 0; r < slopes.size(); ++r) {
    const std::string sampler = slopes.at(r, "sampler").csv(0);
    const std::string depth = slopes.at(r, "depth").csv(0);
    plot.plot += fmt::format(
        "{}'render_error.csv' using (strcol(\"sampler\") eq '{}' && column(\"depth\") == {} ? "
        "column(\"spp\") : 1/0):\"rmse\" with linespoints pt 7 ps 0.7 dt {} lc rgb '{}' "
        "title '{} depth {} (slope {})' noenhanced",
        r == 0 ? "" : ", \\\n  ", sampler, depth, depth == "1" ? 1 : 2, colour(sampler), sampler,
        depth, slopes.at(r, "fitted_slope").csv(2, Column::fixed));
  }
  return plot;
}

// The 4-spp images of the full depth side by side, each pixel blown up to be seen.
inline void write_four_spp_sheet(const std::filesystem::path& dir, const RenderStudyOptions& o,
                                 const RenderStudy& study) {
  if (study.four_spp.size() != o.samplers.size()) return;
  const int factor = std::max(1, 192 / std::max(1, o.width));
  std::vector<Image> large;
  for (const Image& image : study.four_spp) large.push_back(upscale_nearest(image, factor));
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < large.size(); ++i)
    cells.push_back({&large[i], name_of(o.samplers[i])});
  SheetLayout layout;
  layout.columns = static_cast<int>(cells.size());
  layout.title = fmt::format("{} at 4 spp, depth {}", o.scene.scene, o.full_depth);
  write_png(dir / "render_4spp.png", make_contact_sheet(cells, layout));
}

// The study's files (render_error.csv, render_slopes.csv, their plot, render_4spp.png), its
// part of summary.json, and its table on the console.
inline void write_render_study(const std::filesystem::path& dir, const RenderStudyOptions& o,
                               const RenderStudy& study, Json& summary, bool quiet) {
  if (o.max_spp == 0) return;
  write_csv(dir / "render_error.csv", study.errors);
  write_csv(dir / "render_slopes.csv", study.slopes);
  write_plot(dir, render_error_plot(o, study.slopes));
  write_four_spp_sheet(dir, o, study);
  summary["render"] = {{"scene", o.scene.scene},       {"width", o.width},
                       {"height", o.height},           {"depths", study_depths(o)},
                       {"rays", study.rays},           {"slopes", study.slopes.json()},
                       {"errors", study.errors.json()}};
  if (!quiet)
    fmt::print("path tracer, {} {}x{}, rms error against spp:\n{}", o.scene.scene, o.width,
               o.height, study.slopes.console());
}

}  // namespace mcrt::ch09
