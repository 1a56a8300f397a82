#pragma once
// Chapter 09's figures, gnuplot scripts over its CSV files (columns by name): the rms error
// against N of each study with its theory lines, the error at a budget against k, and the
// point sets side by side with their strata drawn.

#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/plot.hpp"
#include "io/table.hpp"
#include "samplers.hpp"

namespace mcrt::ch09 {

// One colour per series label, the same in every plot.
inline std::string colour_of(const std::string& label) {
  if (label == "independent") return "#d62728";
  if (label == "jittered") return "#1f77b4";
  if (label == "latin_hypercube") return "#ff7f0e";
  if (label == "sobol_xor") return "#9467bd";
  if (label == "sobol_owen") return "#2ca02c";
  if (label == "halton") return "#8c564b";
  return "#17becf";  // sobol_owen_odd_n
}

// `study`'s rms error against N for every series of slopes.csv, each with error bars
// +- rmse / sqrt(2 R) (the standard error of a root mean square of R squared errors) and its
// theory line (theory_line: sigma/sqrt(N) for independent points, else the predicted slope
// through the series' centre).
inline Plot error_plot(const std::string& study, const Table& errors, const Table& slopes,
                       const std::string& what) {
  Plot plot;
  plot.name = study + "_error_vs_n";
  plot.title = what + ": rms error against N over the randomisations";
  plot.x_label = "points N";
  plot.y_label = "rms error";
  plot.log_x = plot.log_y = true;
  plot.width = 1000;
  plot.height = 700;
  plot.settings = "set key outside right top\nset autoscale xfix\n";
  plot.x_values = errors.numbers("n");
  plot.y_values = errors.numbers("rmse");
  plot.plot = "plot ";
  bool first = true;
  for (std::size_t r = 0; r < slopes.size(); ++r) {
    if (slopes.at(r, "study").csv(0) != study) continue;
    const std::string label = slopes.at(r, "sampler").csv(0);
    const std::string rows =
        fmt::format("(strcol(\"sampler\") eq '{}' ? column(\"n\") : 1/0)", label);
    plot.plot += fmt::format(
        "{}'{}.csv' using {}:\"rmse\":(column(\"rmse\") / sqrt(2 * column(\"trials\"))) with "
        "yerrorbars pt 7 ps 0.7 lc rgb '{}' title '{} (slope {})' noenhanced, \\\n"
        "  '' using {}:\"theory_line\" with lines dt 2 lc rgb '{}' title 'N^{{{}}}'",
        first ? "" : ", \\\n  ", study, rows, colour_of(label), label,
        slopes.at(r, "fitted_slope").csv(2, Column::fixed), rows, colour_of(label),
        slopes.at(r, "predicted_slope").csv(2, Column::fixed));
    first = false;
  }
  return plot;
}

// The relative error at the budget against k for each method of dimension.csv, with the
// theory of independent points, sigma_k / (I_k sqrt(N)).
inline Plot dimension_plot(std::uint32_t budget, const Table& dimension) {
  Plot plot;
  plot.name = "error_vs_dimension";
  plot.title = fmt::format("e^{{-|x|^2}} on [0,1]^D at N = {}: relative error against D", budget);
  plot.x_label = "dimension D";
  plot.y_label = "relative error (rmse / I)";
  plot.log_y = true;
  plot.width = 1000;
  plot.height = 650;
  plot.settings = "set key outside right top\nset autoscale xfix\nset xtics 1\n";
  plot.x_values = dimension.numbers("dims");
  plot.y_values = dimension.numbers("relative_error");
  const auto rows = [](const char* method, const char* value) {
    return fmt::format("(strcol(\"method\") eq '{}' ? column(\"dims\") : 1/0):{}", method, value);
  };
  plot.plot = fmt::format(
      "plot 'dimension.csv' using {} with linespoints pt 7 lc rgb '{}' title 'independent', \\\n"
      "  '' using {} with lines dt 2 lw 2 lc rgb '{}' title 'theory sigma/(I sqrt N)', \\\n"
      "  '' using {} with linespoints pt 5 lc rgb '{}' title 'Latin hypercube', \\\n"
      "  '' using {} with linespoints pt 9 lc rgb '{}' title \"Sobol' (Owen)\", \\\n"
      "  '' using {} with linespoints pt 11 lc rgb '#1f77b4' title 'trapezoid, floor(N^{{1/D}}) per axis'",
      rows("independent", "\"relative_error\""), colour_of("independent"),
      rows("independent", "(column(\"theory_rmse\") / column(\"reference\"))"),
      colour_of("independent"), rows("latin_hypercube", "\"relative_error\""),
      colour_of("latin_hypercube"), rows("sobol_owen", "\"relative_error\""),
      colour_of("sobol_owen"), rows("trapezoid", "\"relative_error\""));
  return plot;
}

// The n points of each set in [0,1)^2, one panel each (3 x 2), with the strata each set fills
// once: jittered, its grid; Latin hypercube, n rows and n columns; Sobol', at n = 2^m the
// 2^floor(m/2) x 2^ceil(m/2) boxes (one of its elementary-box shapes).
inline Plot point_sets_plot(int n) {
  const auto columns_rows = [n](Sampler s) -> std::pair<int, int> {
    const auto un = static_cast<std::uint32_t>(n);
    switch (s) {
      case Sampler::jittered: {
        const auto c = static_cast<int>(JitteredPoints::grid_columns(un));
        return {c, n / c};
      }
      case Sampler::latin_hypercube: return {n, n};
      case Sampler::sobol_xor:
      case Sampler::sobol_owen: {
        if ((un & (un - 1)) != 0) return {1, 1};
        int m = 0;
        while ((1 << m) < n) ++m;
        return {1 << (m / 2), 1 << (m - m / 2)};
      }
      default: return {1, 1};
    }
  };
  Plot plot;
  plot.name = "point_sets";
  plot.title = fmt::format("{} points of each set", n);
  plot.width = 1200;
  plot.height = 820;
  plot.multiplot = true;
  for (std::size_t p = 0; p < std::size(k_samplers); ++p) {
    const Sampler s = k_samplers[p];
    const auto [c, r] = columns_rows(s);
    plot.plot += fmt::format(
        "set origin {:.4f},{:.4f}\nset size 0.3333,0.5\nset size ratio -1\n"
        "set title '{}' noenhanced\nset xrange [0:1]\nset yrange [0:1]\nunset key\n"
        "set xtics 0,{:.17g},1 format ''\nset ytics 0,{:.17g},1 format ''\n"
        "set tics scale 0\nset grid xtics ytics lt 1 lw 1 lc rgb '#999999'\n"
        "set xlabel ''\nset ylabel ''\n"
        "plot 'points.csv' using (strcol(\"sampler\") eq '{}' ? column(\"x\") : 1/0):\"y\" "
        "with points pt 7 ps 0.6 lc rgb '{}'\n",
        static_cast<double>(p % 3) / 3.0, p < 3 ? 0.5 : 0.0, name_of(s), 1.0 / c, 1.0 / r,
        name_of(s), colour_of(name_of(s)));
  }
  return plot;
}

}  // namespace mcrt::ch09
