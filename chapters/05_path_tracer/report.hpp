#pragma once
// Chapter 05's report: the fitted slope, the depth cut's bias, the error plot, summary.json,
// timings.json and the console table, from the run's error Table.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "integration/statistics.hpp"
#include "app/cli.hpp"
#include "io/plot.hpp"
#include "app/reference_cache.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "render/image.hpp"
#include "render/render_totals.hpp"

namespace mcrt {

// rmse_vs_spp.csv: one row per spp, its two-render RMS error, its RMS error against the
// reference (empty without one) and the cost of both renders.
inline Table rmse_table() {
  return Table({{"spp", Column::integer},
                {"rmse", Column::real, 9},  // sqrt(mean over pixels and channels of (A - B)^2 / 2)
                {"rmse_vs_reference", Column::real, 9},  // sqrt(mean of (A - R)^2)
                {"seconds", Column::real, 6},
                {"rays", Column::integer},
                {"rays_per_second", Column::real, 6}});
}

// depth_bias.csv: per --bias-depths depth and spp, the two errors of a pair rendered at that
// depth (the same samples as the main pairs, cut shallower).
inline Table depth_bias_table() {
  return Table({{"depth", Column::integer},
                {"spp", Column::integer},
                {"rmse", Column::real, 9},               // two-render: noise only
                {"rmse_vs_reference", Column::real, 9},  // noise and the cut's bias
                {"rays", Column::integer}});
}

// The slope of log RMS error against log spp; NaN with fewer than two points or a zero error.
inline double fitted_slope(const Table& errors) {
  const std::vector<double> spp = errors.numbers("spp"), rmse = errors.numbers("rmse");
  const bool can_fit =
      spp.size() >= 2 && std::all_of(rmse.begin(), rmse.end(), [](double e) { return e > 0.0; });
  return can_fit ? fit_log_log(spp, rmse).slope : std::nan("");
}

// The bias the depth cut leaves, estimated at the largest spp: the error against the reference
// less the noise of A (two-render) and of R, sqrt(max(0, E_ref^2 - E_AB^2 - E_R^2)). NaN
// without a reference.
inline double depth_cut_bias_rms(const Table& errors, const Reference* reference) {
  if (reference == nullptr) return std::nan("");
  const std::size_t last = errors.size() - 1;
  const double against_reference = errors.at(last, "rmse_vs_reference").number();
  const double noise = errors.at(last, "rmse").number();
  const double reference_noise = reference->info.value("standard_error_rms", 0.0);
  return std::sqrt(std::max(0.0, against_reference * against_reference - noise * noise -
                                     reference_noise * reference_noise));
}

// rmse_vs_spp.png: the run's two errors at --depth in black and, with a reference, those of
// each --bias-depths depth in a colour of its own (depth_bias.csv): the two-render error
// (solid, open points) falls as spp^-1/2 at every depth; the error against the reference
// (dashed, filled points) follows it until the noise is below the cut's bias, then levels off.
inline void write_rmse_plot(const auto& o, const Table& errors, double slope, const Table* bias) {
  // The reference line of slope -1/2 passes through the first point.
  std::string settings =
      fmt::format("rmse1 = {:.9g}\nspp1 = {}\nset key bottom left font ',10' spacing 1.1\n",
                  errors.at(0, "rmse").number(), o.spp.front()) +
      (std::isfinite(slope)
           ? fmt::format("set label 1 'depth {}: fitted slope {:.3f} (theory -0.5)' at graph "
                         "0.98, graph 0.95 right\n",
                         o.depth, slope)
           : std::string());
  if (o.spp.size() > 1)  // the x axis ends where the data end
    settings += fmt::format("set xrange [{}:{}]\n", o.spp.front(), o.spp.back());
  Plot plot{"rmse_vs_spp",
            bias ? "RMS error against spp: two renders see only noise; the reference also sees "
                   "the depth cut's bias"
                 : "RMS error against samples per pixel",
            "samples per pixel",
            "RMS error",
            true,
            true,
            settings,
            fmt::format("plot 'rmse_vs_spp.csv' using \"spp\":\"rmse\" with linespoints pt 6 "
                        "ps 1.3 lw 2 lc 'black' title 'depth {}: two renders (noise)', rmse1 * "
                        "(x / spp1)**-0.5 with lines dt 3 lc 'gray40' title 'slope -1/2'",
                        o.depth)};
  plot.width = 1000;
  plot.height = 650;
  plot.x_values = errors.numbers("spp");  // one spp, or zero error (no light): still a plot
  plot.y_values = errors.numbers("rmse");
  if (bias) {
    plot.plot += fmt::format(
        ", 'rmse_vs_spp.csv' using \"spp\":\"rmse_vs_reference\" with "
        "linespoints pt 7 ps 1.1 lw 2 dt 2 lc 'black' title 'depth {}: "
        "against the reference (noise and bias)'",
        o.depth);
    // One colour per study depth; its rows of depth_bias.csv picked by the depth column.
    const auto of_depth = [](int depth, const char* column) {
      return fmt::format(
          "'depth_bias.csv' using \"spp\":(column(\"depth\") == {} ? "
          "column(\"{}\") : NaN)",
          depth, column);
    };
    static constexpr const char* k_colours[] = {"#d62728", "#1f77b4", "#2ca02c",
                                                "#9467bd", "#ff7f0e", "#8c564b"};
    for (std::size_t i = 0; i < o.bias_depths.size(); ++i) {
      const int depth = o.bias_depths[i];
      const char* colour = k_colours[i % std::size(k_colours)];
      plot.plot += fmt::format(
          ", {} with linespoints pt 6 ps 1.3 lw 2 lc rgb '{}' title 'depth {}: two renders', "
          "{} with linespoints pt 7 ps 1.1 lw 2 dt 2 lc rgb '{}' title 'depth {}: against the "
          "reference'",
          of_depth(depth, "rmse"), colour, depth, of_depth(depth, "rmse_vs_reference"), colour,
          depth);
    }
    const std::vector<double> against = errors.numbers("rmse_vs_reference");
    plot.y_values.insert(plot.y_values.end(), against.begin(), against.end());
    for (const char* column : {"rmse", "rmse_vs_reference"}) {
      const std::vector<double> values = bias->numbers(column);
      plot.y_values.insert(plot.y_values.end(), values.begin(), values.end());
    }
  }
  write_plot(o.common.dir, plot);
}

inline void write_summary(const Chapter& chapter, const CLI::App& app, const auto& o,
                          const Table& errors, double slope, const RenderTotals& total,
                          const Image& last, const Reference* reference, const Table& bias,
                          std::uint64_t smallpt_rays) {
  Json summary = start_summary(chapter.name, o.common.seed);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  summary["depth"] = o.depth;
  add_render_totals(summary, total);
  summary["smallpt_rays"] = smallpt_rays;  // smallpt.png's render, counted in "rays" too
  summary["rmse_slope"] = std::isfinite(slope) ? Json(slope) : Json(nullptr);  // < 2 spp
  summary["rmse_slope_theory"] = -0.5;
  summary["mean_radiance"] = mean_radiance(last);
  summary["rmse_vs_spp"] = errors.json();
  const double bias_rms = depth_cut_bias_rms(errors, reference);
  summary["depth_cut_bias_rms"] = std::isfinite(bias_rms) ? Json(bias_rms) : Json(nullptr);
  summary["bias_depths"] = reference ? Json(o.bias_depths) : Json(nullptr);
  summary["depth_bias"] = bias.json();  // empty without a reference
  summary["mean_radiance_reference"] =
      reference ? Json(mean_radiance(reference->image)) : Json(nullptr);
  summary["reference"] = reference ? Json(reference->info) : Json(nullptr);
  if (reference) summary["reference"].erase("seconds");  // the machine's: timings.json's
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(chapter.name, o.common.threads);
  add_render_timings(timings, total);
  if (reference && reference->info.contains("seconds"))
    timings["reference_seconds"] = reference->info["seconds"];
  write_timings(o.common.dir, timings, run_flags_json(app));
}

inline void print_table(const Chapter& chapter, const auto& o, const Table& errors, double slope,
                        const RenderTotals& total, const Image& last, const Reference* reference) {
  fmt::print("{}  scene {}  {}x{}  depth {}  {} threads\n", chapter.name, o.scene.scene,
             o.image.width, o.image.height, o.depth, o.common.threads);
  fmt::print("{}",
             errors.console({"spp", "rmse", "rmse_vs_reference", "seconds", "rays_per_second"}));
  if (std::isfinite(slope))
    fmt::print("  fitted slope of log RMS error against log spp: {:.3f} (theory -0.5)\n", slope);
  if (reference)
    fmt::print(
        "  rmse = two-render estimate (noise only); rmse_vs_reference also holds the "
        "depth cut's bias, about {:.3g} RMS\n  mean radiance {:.5g}, reference {:.5g} "
        "(without a depth cut)\n",
        depth_cut_bias_rms(errors, reference), mean_radiance(last),
        mean_radiance(reference->image));
  fmt::print("  rays traced {} in {:.2f} s: {:.4g} rays/s;  non-finite samples {}\n", total.rays,
             total.seconds, total.rays_per_second(), total.non_finite_samples);
  fmt::print(
      "  wrote {}/{{spp_NNNN.png,.pfm, noise_strip.png, rmse_vs_spp.csv,.png, "
      "depth_bias.csv (with a reference), smallpt.png (unless --smallpt-spp 0), "
      "summary.json, timings.json}}\n",
      o.common.out.string());
}

}  // namespace mcrt
