#pragma once
// Chapter 02's figures, written as gnuplot scripts over its CSV files (columns by name).

#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/plot.hpp"

namespace mcrt {

// rmse with error bars +- rmse / sqrt(2 T) (the standard error of a root mean square of T
// near-normal squared errors), the theory line, and a slope -1/2 guide above it.
inline Plot error_plot(double fitted_slope, double guide_constant) {
  Plot plot;
  plot.name = "error_vs_n";
  plot.title = fmt::format("Disk area 4M/N: rms error against N (fitted slope {:.3f}, theory -1/2)",
                           fitted_slope);
  plot.x_label = "points N";
  plot.y_label = "rms error of 4M/N";
  plot.log_x = plot.log_y = true;
  plot.settings =
      fmt::format("set key bottom left\nset autoscale xfix\nguide(n) = {:.6g} / sqrt(n)\n",
                  guide_constant);
  plot.plot =
      "plot 'disk_area.csv' using \"n\":\"rmse\":(column(\"rmse\") / sqrt(2 * column(\"trials\"))) "
      "with yerrorbars pt 7 lc rgb '#1f77b4' title 'rmse over the trials', \\\n"
      "  '' using \"n\":\"theory_std\" with lines lw 2 lc rgb '#d62728' "
      "title 'theory 4 sqrt(η(1-η)/N)', \\\n"
      "  '' using \"n\":(guide(column(\"n\"))) with lines dt 2 lc rgb '#555555' title 'slope -1/2'";
  return plot;
}

// The points of the picture, inside in blue and outside in orange, and the circle.
inline Plot picture_plot(int points, double estimate) {
  Plot plot;
  plot.name = "points";
  plot.title = fmt::format("{} points: 4M/N = {:.4f}  (pi = 3.1416)", points, estimate);
  plot.x_label = "x";
  plot.y_label = "y";
  plot.width = plot.height = 700;
  plot.settings =
      "set size ratio -1\nset xrange [-1:1]\nset yrange [-1:1]\nset key outside top center horizontal\n"
      "set object 1 circle at 0,0 size 1 front fillstyle empty border lc rgb 'black' lw 2\n";
  plot.plot =
      "plot 'points.csv' using \"x\":(column(\"inside\") > 0 ? column(\"y\") : 1/0) with points "
      "pt 7 ps 0.4 lc rgb '#1f77b4' title 'inside', \\\n"
      "  '' using \"x\":(column(\"inside\") > 0 ? 1/0 : column(\"y\")) with points pt 7 ps 0.4 "
      "lc rgb '#ff7f0e' title 'outside'";
  return plot;
}

// The relative error rmse / V_k against N for each k of the ball error study, with its theory
// line sqrt((1 - q) / (q N)), q = V_k / 2^k: parallel lines of slope -1/2 whose constant grows
// with k, the lesson of the ball.
inline Plot ball_error_plot(const std::vector<int>& dims) {
  Plot plot;
  plot.name = "ball_error_vs_n";
  plot.title = "D-ball volume 2^D M/N: relative rms error against N (the constant grows with D)";
  plot.x_label = "points N";
  plot.y_label = "relative rms error of 2^D M/N  (rmse / |B_D|)";
  plot.log_x = plot.log_y = true;
  plot.settings = "set key bottom left\nset autoscale xfix\n";
  const char* colours[] = {"#1f77b4", "#2ca02c", "#d62728"};
  plot.plot = "plot ";
  for (std::size_t s = 0; s < dims.size(); ++s)
    plot.plot += fmt::format(
        "{0}'ball_error_vs_n.csv' using \"n\":(column(\"k\") == {1} ? column(\"relative_rmse\") : "
        "1/0) with points pt 7 lc rgb '{2}' title 'D = {1}: rmse / |B_{{{1}}}|', \\\n"
        "  '' using \"n\":(column(\"k\") == {1} ? column(\"relative_theory_std\") : 1/0) with "
        "lines lw 2 lc rgb '{2}' title 'D = {1}: theory'",
        s ? ", \\\n  " : "", dims[s], colours[s % 3]);
  return plot;
}

}  // namespace mcrt
