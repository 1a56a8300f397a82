#pragma once
// Chapter 07's variance study: for every pdf, two independent renders of the furnace and two
// of the scene at --spp, and the variance of one sample they measure without a reference,
// spp E[(A - B)^2] / 2 = Var[one sample]. One row per pdf (variance_vs_m.csv); the renders go
// through the chapter's estimator, render_with(scene, camera, pdf, spp, first_sample).

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/progress.hpp"
#include "io/table.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"
#include "render/two_render_error.hpp"

namespace mcrt {

inline constexpr int k_furnace_side = 32;  // the furnace study's image: 32 x 32 pixels

// variance_vs_m.csv: one row per pdf. Variances are of ONE sample, per pixel and channel.
inline Table variance_table() {
  return Table({{"pdf", Column::text},
                {"m", Column::integer},                        // empty for the grazing pdf
                {"furnace_variance", Column::real, 9},         // measured, spp (A - B)^2 / 2
                {"furnace_variance_theory", Column::real, 9},  // empty where infinite
                {"furnace_mean", Column::real, 9},
                {"furnace_mean_theory", Column::real, 9},
                {"scene_variance", Column::real, 9},
                {"scene_variance_vs_uniform", Column::real, 6},
                {"scene_mean", Column::real, 9},
                {"scene_seconds", Column::real, 6},  // both renders of the scene
                {"scene_rays", Column::integer}});
}

// Two independent renders at spp (samples [0, spp) and [spp, 2 spp)) and the variance of one
// sample they measure, spp x mean of (A - B)^2 / 2. A is kept.
struct PairResult {
  RenderResult a;
  RenderTotals cost;
  double variance = 0.0;
};
inline PairResult render_pair(const auto& render_with, const Scene& scene, const Camera& camera,
                              const HemispherePdf& pdf, int spp) {
  PairResult pair{render_with(scene, camera, pdf, spp, 0), {}, 0.0};
  const RenderResult b = render_with(scene, camera, pdf, spp, static_cast<std::uint64_t>(spp));
  pair.cost = totals_of(pair.a);
  pair.cost.add(b);
  pair.variance = spp * two_render_mean_squared_error(pair.a.image, b.image);
  return pair;
}

inline void add_totals(RenderTotals& total, const RenderTotals& more) {
  total.rays += more.rays;
  total.non_finite_samples += more.non_finite_samples;
  total.seconds += more.seconds;
}

// The study: one row per pdf; keeps each pdf's first scene image (A) for the outputs.
struct Study {
  Table variances = variance_table();
  std::vector<RenderResult> images;  // A of the scene, per pdf
  RenderTotals total;
};
inline Study run_study(const auto& render_with, const Scene& scene, const Camera& camera,
                       const std::vector<HemispherePdf>& pdfs, const auto& o) {
  const SceneParams& f = o.scene.params;
  const Scene furnace = make_furnace(f.furnace_albedo, f.furnace_emission);
  const Camera furnace_camera(furnace.camera, k_furnace_side, k_furnace_side);
  ProgressBar progress("ch07 pdfs", pdfs.size(), o.common.quiet);
  Study study;
  double uniform_variance = std::nan("");
  for (const HemispherePdf& pdf : pdfs) {
    const PairResult in_furnace = render_pair(render_with, furnace, furnace_camera, pdf, o.spp);
    PairResult in_scene = render_pair(render_with, scene, camera, pdf, o.spp);
    if (pdf.kind == HemispherePdf::uniform) uniform_variance = in_scene.variance;
    const double theory =
        furnace_radiance_variance(pdf, f.furnace_albedo, f.furnace_emission, o.depth);
    study.variances.add_row(
        {pdf_name(pdf), pdf.kind == HemispherePdf::grazing ? Cell{} : Cell{pdf.m},
         in_furnace.variance, std::isfinite(theory) ? Cell{theory} : Cell{},
         mean_radiance(in_furnace.a.image),
         furnace_radiance(f.furnace_albedo, f.furnace_emission, o.depth), in_scene.variance,
         in_scene.variance / uniform_variance, mean_radiance(in_scene.a.image),
         in_scene.cost.seconds, in_scene.cost.rays});
    add_totals(study.total, in_furnace.cost);
    add_totals(study.total, in_scene.cost);
    study.images.push_back(std::move(in_scene.a));
    progress.advance();
  }
  progress.finish();
  return study;
}

}  // namespace mcrt
