#pragma once
// Chapter 04's report: the equal-cost verdict, summary.json, timings.json and the console
// tables, from the run's Tables.

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "plan.hpp"
#include "render/recursive_render.hpp"

namespace mcrt {

// rays.csv: per N and k, the rays traced against the N^k bound, their time and the image's mean.
inline Table rays_table() {
  return Table({{"branching", Column::integer},
                {"depth", Column::integer},
                {"rays", Column::integer},
                {"predicted_max_rays", Column::integer},
                {"seconds", Column::real, 6},
                {"rays_per_second", Column::real, 6},
                {"mean_radiance", Column::real, 9}});
}

// missing_light.csv: the mean radiance at each k against the deep limit, and the part missing.
inline Table missing_light_table() {
  return Table({{"depth", Column::integer},
                {"mean_radiance", Column::real, 9},
                {"limit_mean_radiance", Column::real, 9},
                {"missing_fraction", Column::real, 6}});
}

// The equal-cost verdict in one sentence: which N has the smallest error at the budget.
inline std::string conclusion(const auto& o, const Table& equal, std::size_t best) {
  const std::vector<double> error = equal.numbers("rms_error_at_budget");
  const auto worst =
      static_cast<std::size_t>(std::max_element(error.begin(), error.end()) - error.begin());
  const auto n = [&](std::size_t row) { return equal.at(row, "branching").number(); };
  const auto spp = [&](std::size_t row) { return equal.at(row, "spp").number(); };
  return fmt::format(
      "At equal cost ({} rays per pixel, depth {}) N = {} with {} spp has the "
      "smallest error, {:.3g}; N = {} with {} spp has {:.2f}x more. {}",
      o.budget, o.equal_cost_depth, n(best), spp(best), error[best], n(worst), spp(worst),
      error[best] > 0.0 ? error[worst] / error[best] : 1.0,
      n(best) == 1 ? "Spend rays on camera samples, not on branches: one path "
                     "per sample is chapter 05's path tracer."
                   : "Here branching paid off.");
}

// summary.json: the setup, the totals, every table and the equal-cost verdict; timings.json.
inline void write_summary(const Chapter& chapter, const CLI::App& app, const auto& o,
                          const Plan& plan, const RecursiveRenderer& work, const Table& rays,
                          const Table& missing, const Table& equal, std::size_t best,
                          const std::string& verdict, int light_spp) {
  Json summary = start_summary(chapter.name, o.common.seed);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  summary["branching"] = o.branching;
  summary["max_depth"] = o.max_depth;
  summary["predicted_max_rays"] = plan.predicted_rays;
  add_render_totals(summary, work.total);
  summary["sweep"] = rays.json();
  summary["limit"] = {{"branching", 1},
                      {"depth", plan.limit_depth},
                      {"spp", light_spp},
                      {"mean_radiance", missing.at(0, "limit_mean_radiance").number()}};
  summary["missing_light"] = missing.json();
  summary["grid"] = {{"top_row_spp", o.grid_spp}, {"bottom_row_rays_per_pixel", o.budget}};
  summary["equal_cost"] = {{"budget_rays_per_pixel", o.budget},
                           {"depth", o.equal_cost_depth},
                           {"best_branching", equal.at(best, "branching").json()},
                           {"rows", equal.json()},
                           {"conclusion", verdict}};
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(chapter.name, o.common.threads);
  add_render_timings(timings, work.total);
  write_timings(o.common.dir, timings, run_flags_json(app));
}

// The console: the sweep, the missing light, the equal-cost table and the verdict.
inline void print_tables(const Chapter& chapter, const auto& o, const RenderTotals& total,
                         const Table& rays, const Table& missing, const Table& equal,
                         const std::string& verdict, int light_spp) {
  fmt::print("{}  scene {}  {}x{}  {} spp  {} threads\n{}", chapter.name, o.scene.scene,
             o.image.width, o.image.height, o.spp, o.common.threads, rays.console());
  fmt::print("missing light: 1 - mean L(k) / limit, both with N = 1 and {} spp\n{}", light_spp,
             missing.console());
  fmt::print("equal cost: {} rays per pixel, depth {}\n{}", o.budget, o.equal_cost_depth,
             equal.console({"branching", "spp", "rays_per_pixel", "rms_error",
                            "rms_error_at_budget", "relative_rms_error"}));
  fmt::print("{}\ntotal: {} rays in {:.2f} s ({:.3g} rays/s)\n", verdict, total.rays, total.seconds,
             total.rays_per_second());
  fmt::print(
      "wrote {}/{{rays,missing_light,equal_cost}}.csv, grid.png, plots, summary.json, timings.json\n",
      o.common.out.string());
}

}  // namespace mcrt
