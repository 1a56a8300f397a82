#pragma once
// Chapter 06's report: summary.json, timings.json and the console tables, from the run's Tables.

#include <cmath>
#include <cstddef>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "render/russian_roulette.hpp"

namespace mcrt {

// The q of efficiency.csv's best row (the most efficient fixed q).
inline double best_q(const Table& efficiency) {
  for (std::size_t i = 0; i < efficiency.size(); ++i)
    if (efficiency.at(i, "best_efficiency").number() == 1.0) return efficiency.at(i, "q").number();
  return std::nan("");
}

// How many rows of bias.csv have 0 inside roulette's interval (all of them, but 1% of runs).
inline int rows_with_zero_in_ci(const Table& bias) {
  int rows = 0;
  for (std::size_t i = 0; i < bias.size(); ++i)
    rows += std::abs(bias.at(i, "roulette_bias").number()) <= bias.at(i, "roulette_ci").number();
  return rows;
}

// summary.json: the setup, the totals, the furnace's closed forms beside the measured, every
// table; timings.json: the times and the q they find most efficient. `r` holds the tables
// (bias, efficiency, lengths, renders, splitting), fixed_paths and total.
inline void write_summary(const Chapter& chapter, const CLI::App& app, const auto& o,
                          const auto& r) {
  const double a = o.scene.params.furnace_albedo, le = o.scene.params.furnace_emission;
  const int d = o.roulette.min_depth;
  Json summary = start_summary(chapter.name, o.common.seed);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  summary["depth"] = o.depth;
  summary["min_depth"] = d;
  summary["policy"] = o.roulette.policy == RoulettePolicy::fixed ? "fixed" : "throughput";
  add_render_totals(summary, r.total);
  const std::size_t last = r.efficiency.size() - 1;  // the throughput row
  const double variance = furnace_roulette_variance(a, le, d, o.roulette.q);
  const auto finite = [](double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); };
  summary["furnace"] = {
      {"albedo", a},
      {"emission", le},
      {"paths", o.paths},
      {"radiance_theory", furnace_radiance_untruncated(a, le)},
      {"variance_threshold_q", furnace_roulette_variance_threshold(a)},
      {"fixed_q",
       {{"q", o.roulette.q},
        {"mean", r.fixed_paths.radiance.mean()},
        {"standard_error", r.fixed_paths.radiance.standard_error()},
        {"variance", r.fixed_paths.radiance.variance()},
        {"variance_theory", finite(variance)},
        {"mean_path_length", r.fixed_paths.rays.mean()},
        {"mean_path_length_theory", furnace_roulette_mean_rays(d, o.roulette.q)}}},
      {"throughput",
       {{"floor", o.roulette.floor},
        {"mean", r.efficiency.at(last, "mean").number()},
        {"standard_error", std::sqrt(r.efficiency.at(last, "variance").number() / o.paths)},
        {"mean_path_length", r.efficiency.at(last, "rays_per_path").number()}}}};
  summary["mean_path_length"] = r.fixed_paths.rays.mean();
  summary["mean_path_length_theory"] = furnace_roulette_mean_rays(d, o.roulette.q);
  summary["bias_rows_with_zero_in_roulette_ci"] = rows_with_zero_in_ci(r.bias);
  summary["bias"] = r.bias.json();
  summary["efficiency"] = r.efficiency.json();
  summary["path_length"] = r.lengths.json();
  summary["splitting"] = r.splitting.json();
  summary["renders"] = r.renders.json();
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(chapter.name, o.common.threads);
  add_render_timings(timings, r.total);
  timings["best_q"] = best_q(r.efficiency);  // chosen by measured efficiency
  write_timings(o.common.dir, timings, run_flags_json(app));
}

// The console: the furnace, its four studies, the renders.
inline void print_tables(const Chapter& chapter, const auto& o, const auto& r) {
  const double a = o.scene.params.furnace_albedo;
  fmt::print("{}  furnace a = {}, Le = {}: E[L] = Le / (1 - a) = {:.6g}   {} paths per row\n",
             chapter.name, a, o.scene.params.furnace_emission,
             furnace_radiance_untruncated(a, o.scene.params.furnace_emission), o.paths);
  fmt::print("bias: the depth cut at k against roulette after k bounces (ci: 99.9%)\n{}",
             r.bias.console(
                 {"k", "cut_bias", "cut_bias_theory", "cut_ci", "roulette_bias", "roulette_ci"}));
  fmt::print(
      "efficiency = 1 / (variance x seconds per path); fixed q <= 4a^2/3 = {:.4g} has "
      "infinite variance\n{}",
      furnace_roulette_variance_threshold(a),
      r.efficiency.console({"policy", "q", "mean", "variance", "variance_theory", "rays_per_path",
                            "efficiency", "best_efficiency"}));
  fmt::print("path length at q = {}: mean {:.4f} rays, theory d + 1/(1 - q) = {:.4f}\n",
             o.roulette.q, r.fixed_paths.rays.mean(),
             furnace_roulette_mean_rays(o.roulette.min_depth, o.roulette.q));
  fmt::print(
      "splitting: the first hit as n paths of 1/n its weight, fixed-q roulette after d "
      "= {}; efficiency = 1 / (variance x rays per path)\n{}",
      o.roulette.min_depth,
      r.splitting.console({"q", "n", "paths", "variance", "variance_theory", "rays_per_path",
                           "efficiency", "efficiency_theory"}));
  fmt::print("scene {}  {}x{}  {} spp\n{}", o.scene.scene, o.image.width, o.image.height, o.spp,
             r.renders.console());
  fmt::print(
      "wrote {}/{{bias,efficiency,path_length,splitting,renders}}.csv and plots, "
      "{{depth_cut,roulette}}.png/.pfm, summary.json, timings.json\n",
      o.common.out.string());
}

}  // namespace mcrt
