#pragma once
// Chapter 04's figures: gnuplot scripts over its CSV files (columns by name), and the grid of
// every image of the sweep.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/plot.hpp"
#include "io/table.hpp"
#include "render/image.hpp"

namespace mcrt {

// The a of the guide a^(k+1) to the missing fractions m_k = 1 - L(k) / limit: the least-squares
// fit of log m_k = (k + 1) log a over the positive m_k (in the furnace m_k = a^(k+1) exactly,
// a its albedo); 0 when none is positive.
inline double fitted_albedo(const std::vector<double>& missing) {
  double sum_xy = 0.0, sum_xx = 0.0;
  for (std::size_t k = 0; k < missing.size(); ++k)
    if (missing[k] > 0.0) {
      const double x = static_cast<double>(k + 1);
      sum_xy += x * std::log(missing[k]);
      sum_xx += x * x;
    }
  return sum_xx > 0.0 ? std::exp(sum_xy / sum_xx) : 0.0;
}

// The missing light 1 - L(k) / limit against k on a log axis, where a geometric decay a^(k+1)
// is a straight line, with that guide. `albedo`: the furnace's a, or 0 to fit it.
inline Plot missing_light_plot(const std::vector<double>& missing, double albedo, int light_spp,
                               int limit_depth) {
  const bool fitted = albedo <= 0.0;
  const double a = fitted ? fitted_albedo(missing) : albedo;
  Plot plot{"missing_light_vs_depth",
            "Missing light against depth: it decays geometrically, a straight line on a log axis",
            "depth k",
            "missing fraction 1 - L(k) / limit",
            false,
            true,
            fmt::format("a = {:.6g}\nset xtics 1\nset autoscale xfix\nset key top right\n", a),
            fmt::format("plot 'missing_light.csv' using \"depth\":"
                        "(column(\"missing_fraction\") > 0 ? column(\"missing_fraction\") : 1/0) "
                        "with linespoints pt 7 lw 3 lc 'black' "
                        "title 'N = 1, {} spp, against the limit at k = {}', a**(x + 1) with lines "
                        "dt 2 lw 2 lc rgb '#d62728' title 'a^{{k+1}}, a = {:.3f}{}'",
                        light_spp, limit_depth, a,
                        fitted ? " (fitted: the effective albedo of the scene)" : " (the albedo)")};
  plot.y_values = missing;
  if (a > 0.0)
    for (std::size_t k = 0; k < missing.size(); ++k)
      plot.y_values.push_back(std::pow(a, static_cast<double>(k + 1)));
  return plot;
}

// rays_vs_depth, mean_radiance_vs_depth and equal_cost, over rays.csv, missing_light.csv and
// equal_cost.csv; one line per N, picked out by the branching column.
// `radiances` and `errors` are the values the second and third plots draw (all zero without
// light).
inline void write_plots(const std::filesystem::path& out, const std::vector<int>& branching,
                        int spp, int light_spp, double limit, int limit_depth, int budget,
                        int equal_cost_depth, const std::vector<double>& radiances,
                        const std::vector<double>& errors) {
  const std::string per_n =
      fmt::format("Ns = '{}'\nset xtics 1\nset autoscale xfix\n", fmt::join(branching, " "));
  const auto of_n = [](const char* column) {
    return fmt::format(
        "'rays.csv' using \"depth\":(column(\"branching\") == word(Ns, i) + 0 ? "
        "column(\"{}\") : NaN)",
        column);
  };
  write_plot(out,
             {"rays_vs_depth", "Rays traced against depth: at most N times more per bounce (N^k)",
              "depth k", "rays traced", false, true, per_n + "set key top left\n",
              "plot for [i=1:words(Ns)] " + of_n("rays") +
                  " with linespoints pt 7 lw 2 lc i "
                  "title 'N = '.word(Ns, i), for [i=1:words(Ns)] " +
                  of_n("predicted_max_rays") +
                  " with lines dt 2 lc i title 'N = '.word(Ns, i).' predicted (no escapes)'"});
  Plot radiance{
      "mean_radiance_vs_depth",
      "Mean radiance against depth: the cut at k drops the light of longer paths",
      "depth k",
      "mean radiance of the image",
      false,
      false,
      per_n + fmt::format("limit = {:.9g}\nset key bottom right\nset yrange [0:*]\n"
                          "set offsets 0, 0, graph 0.1, 0\n",
                          limit),
      fmt::format("plot for [i=1:words(Ns)] {} with linespoints pt 7 lw 2 lc i title "
                  "'N = '.word(Ns, i).', {} spp', 'missing_light.csv' using "
                  "\"depth\":\"mean_radiance\" with linespoints pt 5 lw 3 lc 'black' title "
                  "'N = 1, {} spp', limit with lines dt 2 lw 2 lc 'black' title "
                  "'limit (N = 1, k = {}, {} spp)'",
                  of_n("mean_radiance"), spp, light_spp, limit_depth, light_spp)};
  radiance.y_values = radiances;
  write_plot(out, radiance);
  Plot equal{"equal_cost",
             fmt::format("Equal cost: {} rays per pixel at depth {}", budget, equal_cost_depth),
             "branching N",
             "RMS error at the budget",
             true,
             true,
             fmt::format("set key top left\nset format x '%g'\nset xtics ({})\n"
                         "set xrange [{}:{}]\n",
                         fmt::join(branching, ", "), branching.front(), branching.back()),
             "plot 'equal_cost.csv' using \"branching\":\"rms_error_at_budget\" with linespoints "
             "pt 7 lw 2 title 'RMS error'"};
  equal.y_values = errors;
  equal.x_values.assign(branching.begin(), branching.end());  // one N: a range around it
  write_plot(out, equal);
}

// grid.png, two rows, each brightened by `exposure` (radiance times it before the sRGB
// encoding) so the dim walls show. Top: N = 1 at --grid-spp for every k, each under the light
// its cut misses (missing_light.csv): at one spp the columns differ only in the bounces they
// keep. Bottom: the equal-cost renders at --equal-cost-depth, one per N, each under its spp
// and RMS error (equal_cost.csv): the same rays per pixel, more branches buy fewer samples.
// Small images are blown up (nearest neighbour, so the noise stays visible) to about 256 wide.
inline void write_grid(const std::filesystem::path& out, std::vector<Image> by_depth,
                       std::vector<Image> at_equal_cost, const Table& missing, const Table& equal,
                       int grid_spp, int budget, double exposure, int width) {
  const std::size_t columns = std::max(by_depth.size(), at_equal_cost.size());
  std::vector<Image> images;
  std::vector<std::string> labels;
  for (std::size_t k = 0; k < columns; ++k) {
    if (k < by_depth.size()) {
      images.push_back(std::move(by_depth[k]));
      labels.push_back(fmt::format("k={}: {:.1f}% missing", k,
                                   100.0 * missing.at(k, "missing_fraction").number()));
    } else {  // an empty cell: the bottom row is longer
      images.emplace_back(0, 0);
      labels.emplace_back();
    }
  }
  for (std::size_t i = 0; i < columns; ++i) {
    if (i < at_equal_cost.size()) {
      images.push_back(std::move(at_equal_cost[i]));
      labels.push_back(fmt::format("N={} {}spp rms {:.3f}", equal.at(i, "branching").number(),
                                   equal.at(i, "spp").number(), equal.at(i, "rms_error").number()));
    }
  }
  for (Image& image : images)
    for (Color& c : image.pixels) c *= exposure;
  const int factor = std::clamp(256 / width, 1, 4);
  SheetLayout layout;
  layout.columns = static_cast<int>(columns);
  layout.label_scale = width * factor >= 120 ? 2 : 1;
  const double stops = std::log2(exposure);
  const int k = equal.size() > 0 ? static_cast<int>(equal.at(0, "depth").number()) : 0;
  layout.title = fmt::format(
      "top: N=1, {} spp, cut at depth k; bottom: k={}, at most {} rays/pixel each; exposure x{:g} "
      "({:+g} stop{})",
      grid_spp, k, budget, exposure, stops, std::abs(stops) == 1.0 ? "" : "s");
  write_png(out / "grid.png", labelled_grid(images, labels, factor, layout));
}

}  // namespace mcrt
