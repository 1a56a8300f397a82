#pragma once
// Chapter 06's figures: gnuplot scripts over bias.csv, efficiency.csv and path_length.csv,
// columns by name; the closed forms of common/render/russian_roulette.hpp drawn beside them.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "io/plot.hpp"
#include "io/table.hpp"

namespace mcrt {

/// What the plots need besides the CSV files.
struct PlotSetup {
  double albedo = 0.5;
  double emission = 1.0;
  int depth = 10;        ///< bias.csv's largest k
  int min_depth = 3;     ///< d of the efficiency sweep and the path lengths
  double fixed_q = 0.7;  ///< q of path_length.csv
};

// bias.png: the depth cut's bias against k with its closed form, roulette's beside it at 0.
inline void write_bias_plot(const std::filesystem::path& out, const PlotSetup& s,
                            const Table& bias) {
  Plot plot{"bias",
            "Bias against k: the depth cut at k loses Le a^(k+1)/(1-a); roulette after "
            "k loses nothing",
            "k (depth cut, or bounces before roulette)",
            "mean - Le/(1-a)",
            false,
            false,
            fmt::format("set key bottom right\nset autoscale xfix\n{}",
                        s.depth <= 20 ? "set xtics 1\n" : ""),
            "plot 0 with lines lc 'gray' notitle, "
            "'bias.csv' using \"k\":\"cut_bias_theory\" with lines dt 2 lw 2 lc 'black' "
            "title 'depth cut, closed form -Le a^{k+1}/(1-a)', "
            "'' using \"k\":\"cut_bias\":\"cut_ci\" with yerrorbars pt 7 lc 1 "
            "title 'depth cut at k (99.9% interval)', "
            "'' using (column(\"k\") + 0.15):\"roulette_bias\":\"roulette_ci\" with yerrorbars "
            "pt 5 lc 2 title 'roulette after k bounces (99.9% interval)'"};
  plot.y_values = {0.0};  // all of them 0 without light: a range around 0, not an empty one
  for (const char* column : {"cut_bias", "cut_bias_theory", "roulette_bias"})
    for (double y : bias.numbers(column)) plot.y_values.push_back(y);
  write_plot(out, plot);
}

// efficiency.png: measured 1 / (variance x rays per path) of each fixed q, its closed form as
// a curve, the best q ringed, the throughput policy as a line. Rays, not seconds: the figure is
// the same in every run with the seed, and its points are the last row of the page's table
// inverted. Two bands: q <= b = 4a^2/3, where the variance is infinite, and b < q < q4 =
// (16a^4/5)^(1/3), where the fourth moment is (E[w^4] = 16a^4/5 for w = 2a cos, each survival
// divides it by q^3): there the sample variance converges slowly, mostly from below, so those
// points are drawn open and left out of the choice of the best q.
inline void write_efficiency_plot(const std::filesystem::path& out, const PlotSetup& s,
                                  const Table& efficiency) {
  const double a = s.albedo;
  const double q4 = std::cbrt(16.0 * std::pow(a, 4) / 5.0);  // b itself is the script's
  double best_q = std::nan(""), best = 0.0, throughput = 0.0, highest = 0.0, largest_q = 0.0;
  // Without light every variance is 0 and every efficiency infinite: nothing finite to draw.
  const auto finite = [](double x) { return std::isfinite(x) ? x : 0.0; };
  const auto per_ray = [&](std::size_t i) {
    return 1.0 /
           (efficiency.at(i, "variance").number() * efficiency.at(i, "rays_per_path").number());
  };
  for (std::size_t i = 0; i < efficiency.size(); ++i) {
    const double e = per_ray(i);
    highest = std::max(highest, finite(e));
    if (efficiency.at(i, "policy").string() == "throughput") {
      throughput = finite(e);
      continue;
    }
    const double q = efficiency.at(i, "q").number();
    largest_q = std::max(largest_q, q);
    if (q > q4 && std::isfinite(e) && e > best) best_q = q, best = e;
  }
  const std::string settings = fmt::format(
      "a = {:.9g}; Le = {:.9g}; d = {}; q4 = {:.9g}\n"
      "b = 4.0 * a**2 / 3\n"
      "S(q) = (1 - b**(d + 1)) / (1 - b) + b**(d + 1) / (q - b)\n"
      "V(q) = Le**2 * ((1 + a) / (1 - a) * S(q) - 1 / (1 - a)**2)\n"
      "eff(q) = q > b ? 1 / (V(q) * (d + 1 / (1 - q))) : NaN\n"
      "per_ray(v, r) = 1 / (v * r)\n"
      "set samples 500\nset xrange [0:{:.9g}]\nset yrange [0:{:.9g}]\nset key top right\n"
      "if (b < 1) set object 1 rect from first 0, graph 0 to first b, graph 1 "
      "fc rgb '#d0d0d0' fs solid noborder behind\n"
      "if (b < 1) set label 2 'q <= 4a^2/3: infinite variance' at first b / 2, graph 0.45 "
      "center rotate by 90 noenhanced\n"
      "if (q4 > b && q4 < 1) set object 2 rect from first b, graph 0 to first q4, graph 1 "
      "fc rgb '#f0f0f0' fs solid noborder behind\n"
      "if (q4 > b && q4 < 1) set label 3 sprintf('q < %.3f: infinite 4th moment, variance "
      "unreliable', q4) at first (b + q4) / 2, graph 0.45 center rotate by 90 noenhanced "
      "font ',9'\n"
      "{}",
      a, s.emission, s.min_depth, q4, largest_q > 0.0 ? largest_q : 1.0,
      highest > 0.0 ? 1.35 * highest : 1.0,
      std::isfinite(best_q)
          ? fmt::format("set label 1 'best q = {:g}' at first {:.9g}, first {:.9g} point pt 6 "
                        "ps 3 lw 2 offset 1.5, 1.5\n",
                        best_q, best_q, best)
          : std::string());
  const std::string fixed =
      "(stringcolumn(\"policy\") eq 'fixed' && column(\"q\") {} q4 ? "
      "per_ray(column(\"variance\"), column(\"rays_per_path\")) : NaN)";
  write_plot(out, {"efficiency", "Efficiency of fixed-q roulette: 1 / (variance x rays per path)",
                   "q (probability of going on)", "efficiency (1 / (variance x rays))", false,
                   false, settings,
                   fmt::format("plot 'efficiency.csv' using \"q\":{} with points pt 7 ps 1.5 lc 1 "
                               "title 'measured', '' using \"q\":{} with points pt 6 ps 1.5 lw 2 "
                               "lc 1 title 'measured, unreliable (infinite 4th moment)', "
                               "eff(x) with lines dt 2 lw 2 lc 'black' title 'closed form', "
                               "{:.9g} with lines dt 3 lw 2 lc 2 title 'throughput policy "
                               "(measured)'",
                               fmt::format(fmt::runtime(fixed), ">"),
                               fmt::format(fmt::runtime(fixed), "<="), throughput)});
}

// path_length.png: the fraction of paths that traced r rays against the geometric law (rows of
// no paths, r <= d, left out: the axis starts where the paths do).
inline void write_path_length_plot(const std::filesystem::path& out, const PlotSetup& s) {
  write_plot(out, {"path_length",
                   fmt::format("Path lengths at q = {:g}, d = {}: geometric after d + 1 rays",
                               s.fixed_q, s.min_depth),
                   "rays traced by the path", "fraction of paths", false, true,
                   "set key top right\nset autoscale xfix\nset style fill solid 0.4\n",
                   fmt::format("plot 'path_length.csv' using (column(\"fraction\") > 0 ? "
                               "column(\"rays\") : 1/0):\"fraction\" with points pt 7 ps 1.2 lc 1 "
                               "title 'measured', '' using (column(\"probability\") > 0 ? "
                               "column(\"rays\") : 1/0):\"probability\" with lines lw 2 lc 'black' "
                               "title 'q^{{r-d-1}} (1-q), q = {:g}'",
                               s.fixed_q)});
}

// What the plots draw beside the CSV files, from the Options.
inline PlotSetup plot_setup(const auto& o) {
  return {o.scene.params.furnace_albedo, o.scene.params.furnace_emission, o.depth,
          o.roulette.min_depth, o.roulette.q};
}

// bias.png, efficiency.png and path_length.png into `out`, for the run's Options `o`.
inline void write_plots(const std::filesystem::path& out, const auto& o, const Table& efficiency,
                        const Table& bias) {
  const PlotSetup setup = plot_setup(o);
  write_bias_plot(out, setup, bias);
  write_efficiency_plot(out, setup, efficiency);
  write_path_length_plot(out, setup);
}

}  // namespace mcrt
