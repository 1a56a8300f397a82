#pragma once
// Chapter 07's report: summary.json, timings.json and the console tables, from the study's Tables.

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "render/render_totals.hpp"

#include "pdf_study.hpp"

namespace mcrt {

// The cosine pdf's measured variance in the furnace: 0 to rounding (row 1, after uniform).
inline double cosine_furnace_variance(const Table& variances) {
  return variances.at(1, "furnace_variance").number();
}

// summary.json: the setup, the furnace, the totals, both tables and the flags; timings.json.
inline void write_summary(const Chapter& chapter, const CLI::App& app, const auto& o,
                          const Table& variances, const Table& equal_time,
                          const RenderTotals& total) {
  Json summary = start_summary(chapter.name, o.common.seed);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  summary["depth"] = o.depth;
  summary["furnace"] = {{"albedo", o.scene.params.furnace_albedo},
                        {"emission", o.scene.params.furnace_emission},
                        {"width", k_furnace_side},
                        {"height", k_furnace_side},
                        {"cosine_variance", cosine_furnace_variance(variances)}};
  add_render_totals(summary, total);
  summary["variance_vs_m"] = variances.json();
  summary["equal_time"] = equal_time.json();
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(chapter.name, o.common.threads);
  add_render_timings(timings, total);
  write_timings(o.common.dir, timings, run_flags_json(app));
}

// The console: the variance per pdf, the furnace's cosine row, the errors against the
// reference, the totals and what was written.
inline void print_report(const Chapter& chapter, const auto& o, const Table& variances,
                         const Table& equal_time, const RenderTotals& total) {
  fmt::print("{}  scene {}  {}x{}  {} spp  depth {}  {} threads\n", chapter.name, o.scene.scene,
             o.image.width, o.image.height, o.spp, o.depth, o.common.threads);
  fmt::print("  variance of one sample, per pixel (furnace: albedo {}, emission {}):\n",
             o.scene.params.furnace_albedo, o.scene.params.furnace_emission);
  fmt::print("{}", variances.console({"pdf", "furnace_variance", "furnace_variance_theory",
                                      "scene_variance", "scene_variance_vs_uniform"}));
  fmt::print("  furnace variance with the cosine pdf: {:.3g} (0 to rounding)\n",
             cosine_furnace_variance(variances));
  fmt::print("  against the reference:\n{}",
             equal_time.console({"image", "spp", "rays", "seconds", "relative_mse"}));
  fmt::print("  rays traced {} in {:.2f} s: {:.4g} rays/s;  non-finite samples {}\n", total.rays,
             total.seconds, total.rays_per_second(), total.non_finite_samples);
  fmt::print(
      "  wrote {}/{{uniform,cosine,cosine_equal_time,reference}}.{{png,pfm}}, "
      "noise_strip.png, variance_vs_m.csv,.png, equal_time.csv, summary.json, timings.json\n",
      o.common.out.string());
}

}  // namespace mcrt
