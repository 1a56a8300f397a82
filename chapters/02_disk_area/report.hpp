#pragma once
// Chapter 02's report: summary.json, timings.json and the console table, from the studies' Results.

#include <fmt/format.h>

#include "integration/disk_counter.hpp"
#include "app/cli.hpp"
#include "app/summary.hpp"

namespace mcrt {

// summary.json: the disk study's fit and speed, the ball tables, the picture, the flags.
inline Json summary_of(const Chapter& chapter, const CLI::App& app, const auto& o, const auto& r) {
  Json summary = start_summary(chapter.name, o.common.seed);
  summary["disk"] = {{"sizes", r.disk.size()},
                     {"trials", o.trials},
                     {"largest_n", o.max_n},
                     {"estimate_at_largest_n", r.disk.numbers("mean_estimate").back()},
                     {"fitted_slope", r.disk_fit.slope},
                     {"fitted_slope_standard_error", r.disk_fit.slope_standard_error},
                     {"theory_slope", -0.5},
                     {"median_empirical_over_theory_std", r.median_std_ratio},
                     {"samples", r.disk_points}};
  summary["ball"] = {{"n", o.ball_n},
                     {"trials", o.trials},
                     {"volumes", r.balls.json()},
                     {"fitted_slopes", r.ball_slopes.json()}};
  summary["picture"] = {{"points", o.points}, {"estimate", r.picture_estimate}};
  summary["flags"] = flags_json(app);
  return summary;
}

// timings.json: how fast the disk study ran, and on which path.
inline Json timings_of(const Chapter& chapter, const auto& o, const auto& r) {
  Json timings = start_timings(chapter.name, o.common.threads);
  timings["disk"] = {{"seconds", r.disk_seconds},
                     {"samples_per_second", r.disk_points / r.disk_seconds},
                     {"avx2", disk_count_uses_avx2()}};
  return timings;
}

// The console: the disk table, its slope and speed, the ball tables, the picture.
inline void print_report(const Chapter& chapter, const auto& o, const auto& r) {
  fmt::print("{}  N from 10 to {} ({} sizes), {} trials each, seed {}, {} threads\n{}",
             chapter.name, o.max_n, r.disk.size(), o.trials, o.common.seed, o.common.threads,
             r.disk.console({"n", "mean_estimate", "rmse", "theory_std", "empirical_std"}));
  fmt::print(
      "  slope of log(rmse) against log(N): {:.3f} +- {:.3f}  (theory -0.5)\n"
      "  median empirical / theory std: {:.3f}\n",
      r.disk_fit.slope, r.disk_fit.slope_standard_error, r.median_std_ratio);
  fmt::print("  samples per second: {:.3g}  ({:.3g} points in {:.2f} s{})\n",
             r.disk_points / r.disk_seconds, r.disk_points, r.disk_seconds,
             disk_count_uses_avx2() ? ", AVX2" : "");
  fmt::print("  k-ball at N = {}:\n{}  k-ball rmse slopes:\n{}", o.ball_n,
             r.balls.console({"k", "exact_volume", "mean_estimate", "empirical_std", "theory_std",
                              "relative_std"}),
             r.ball_slopes.console());
  fmt::print(
      "  picture: {} points, 4M/N = {:.4f}\n  wrote {}/{{disk_area,ball_volume,"
      "ball_error_vs_n,points}}.csv, plots, summary.json, timings.json\n",
      o.points, r.picture_estimate, o.common.out.string());
}

}  // namespace mcrt
