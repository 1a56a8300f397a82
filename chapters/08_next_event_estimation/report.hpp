#pragma once
// Chapter 08's report: summary.json, timings.json and the console, from its Tables.

#include <fmt/format.h>

#include "io/cli.hpp"
#include "io/render_summary.hpp"
#include "io/summary.hpp"
#include "io/table.hpp"
#include "render/render_totals.hpp"

namespace mcrt {

// summary.json: the setup, the chosen scene's images against the reference, the shoot-out.
inline void write_summary(const Chapter& chapter, const CLI::App& app, const auto& o,
                          const Table& images, const Table& efficiency, const Json& reference,
                          const RenderTotals& total) {
  Json summary = start_summary(chapter, o.common);
  add_render_setup(summary, o.scene, o.image);
  summary["light_scale"] = o.scene.params.light_scale;
  summary["spp"] = o.spp;
  summary["depth"] = o.depth >= 0 ? Json(o.depth) : Json("none: Russian roulette");
  summary["reference"] = reference;
  summary["images"] = images.json();
  summary["shootout"] = efficiency.json();
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(chapter, o.common);
  add_render_timings(timings, total);
  write_timings(o.common.dir, timings, app);
}

inline void print_report(const Chapter& chapter, const auto& o, const Table& images,
                         const Table& efficiency, const RenderTotals& total) {
  fmt::print("{}  scene {} (light scale {})  {}x{}  {} spp  {} threads\n", chapter.name,
             o.scene.scene, o.scene.params.light_scale, o.image.width, o.image.height, o.spp,
             o.common.threads);
  fmt::print("  the chosen scene against its reference:\n{}",
             images.console({"image", "spp", "seconds", "rel_mse"}));
  fmt::print("  the shoot-out (equal time budgets):\n{}",
             efficiency.console({"scene", "light_scale", "estimator", "budget_seconds", "spp",
                                 "rel_mse", "efficiency_vs_uniform"}));
  fmt::print("  rays traced {} in {:.2f} s: {:.4g} rays/s;  non-finite samples {}\n", total.rays,
             total.seconds, total.rays_per_second(), total.non_finite_samples);
  fmt::print("  wrote {}/{{nee,mis}}.{{png,pfm}}, images.csv, efficiency.csv, "
             "relmse_vs_time_N.png, contact_sheet.png, summary.json, timings.json\n",
             o.common.out.string());
}

}  // namespace mcrt
