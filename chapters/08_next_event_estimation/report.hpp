#pragma once
// Chapter 08's report: summary.json, timings.json and the console, from its Tables.

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "render/render_totals.hpp"

#include "shootout.hpp"

namespace mcrt {

// summary.json: the setup, the chosen scene's images against the reference, the shoot-out.
inline void write_summary(const Chapter& chapter, const CLI::App& app, const auto& o,
                          const Table& images, const Shootout& shootout, const Json& reference,
                          const RenderTotals& total, const Table& plates,
                          const Table& light_choice) {
  Json summary = start_summary(chapter.name, o.common.seed);
  add_render_setup(summary, o.scene, o.image);
  summary["light_scale"] = o.scene.params.light_scale;
  summary["spp"] = o.spp;
  summary["depth"] = o.depth >= 0 ? Json(o.depth) : Json("none: Russian roulette");
  summary["reference"] = reference;
  summary["reference"].erase("seconds");  // the machine's: timings.json's
  summary["images"] = images.json();
  summary["shootout"] = shootout.table.json();
  summary["plates"] = plates.json();
  summary["light_choice"] = light_choice.json();
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(chapter.name, o.common.threads);
  add_render_timings(timings, total);
  if (reference.contains("seconds")) timings["reference_seconds"] = reference["seconds"];
  // The same photographs in seconds, every column (Table::json leaves timing columns out).
  Json seconds = Json::array();
  for (std::size_t i = 0; i < shootout.seconds.size(); ++i) {
    Json row = Json::object();
    for (const Column& c : shootout.seconds.columns())
      row[c.name] = shootout.seconds.at(i, c.name).json();
    seconds.push_back(std::move(row));
  }
  timings["shootout"] = std::move(seconds);
  write_timings(o.common.dir, timings, run_flags_json(app));
}

inline void print_report(const Chapter& chapter, const auto& o, const Table& images,
                         const Table& efficiency, const RenderTotals& total) {
  fmt::print("{}  scene {} (light scale {})  {}x{}  {} spp  {} threads\n", chapter.name,
             o.scene.scene, o.scene.params.light_scale, o.image.width, o.image.height, o.spp,
             o.common.threads);
  fmt::print("  the chosen scene against its reference:\n{}",
             images.console({"image", "spp", "rays", "rel_mse"}));
  fmt::print("  the shoot-out (equal ray budgets, rays per pixel):\n{}",
             efficiency.console({"scene", "light_scale", "estimator", "budget_rays_per_pixel",
                                 "spp", "rel_mse", "efficiency_vs_uniform"}));
  fmt::print("  rays traced {} in {:.2f} s: {:.4g} rays/s;  non-finite samples {}\n", total.rays,
             total.seconds, total.rays_per_second(), total.non_finite_samples);
  fmt::print(
      "  wrote {}/{{nee,mis}}.{{png,pfm}}, images.csv, efficiency.csv, "
      "relmse_vs_rays_SCENE.png, contact_sheet.png, plates.png, plates.csv, "
      "light_choice.png, light_choice.csv, summary.json, timings.json\n",
      o.common.out.string());
}

}  // namespace mcrt
