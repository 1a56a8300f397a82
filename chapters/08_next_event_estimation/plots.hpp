#pragma once
// Chapter 08's figures: log relative MSE against log time per scene (efficiency.csv, columns by
// name), and the contact sheet of the equal-time images.

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/plot.hpp"

#include "estimators.hpp"
#include "shootout.hpp"

namespace mcrt {

// relmse_vs_time_<n>.png for shoot-out scene n: one line per estimator, and a line of slope -1
// through the first NEE point (an unbiased estimator's relMSE falls as 1/time). The time axis
// ends where the runs do, often within a decade: tics at 1, 2, 5 times the powers of 10.
inline void write_relmse_plot(const std::filesystem::path& dir, const ShootoutScene& s,
                              std::size_t n) {
  std::string plot = "plot ";
  for (const EstimatorInfo& e : k_estimators)
    plot += fmt::format(
        "'efficiency.csv' using (strcol(\"scene\") eq \"{}\" && abs(column(\"light_scale\") - {}) "
        "< 1e-9 && strcol(\"estimator\") eq \"{}\" ? column(\"seconds\") : 1/0):\"rel_mse\" "
        "with linespoints pt 7 lw 2 title '{}', ",
        s.scene, s.light_scale, e.name, e.label);
  plot += "c / x with lines dt 2 lc 'black' title 'slope -1'";
  const std::string settings = fmt::format(
      "set key outside right\nset autoscale xfix\nset format x '%g'\n"
      "set xtics add (0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 200, 500)\n"
      "stats 'efficiency.csv' using (strcol(\"scene\") eq \"{}\" && "
      "abs(column(\"light_scale\") - {}) < 1e-9 && strcol(\"estimator\") eq \"nee\" ? "
      "column(\"rel_mse\") * column(\"seconds\") : 1/0) nooutput\nc = STATS_min\n",
      s.scene, s.light_scale);
  write_plot(dir, {fmt::format("relmse_vs_time_{}", n),
                   fmt::format("Relative MSE against render time: {}", s.label()),
                   "seconds", "relative MSE", true, true, settings, plot, 1000, 600});
}

// contact_sheet.png: one row per scene, one column per estimator plus the reference, the images
// of the largest budget.
inline void write_contact_sheet(const std::filesystem::path& dir,
                                const std::vector<ShootoutScene>& scenes, const Shootout& result,
                                double budget) {
  std::vector<Image> images;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    for (std::size_t j = 0; j < result.equal_time[i].size(); ++j) {
      images.push_back(result.equal_time[i][j]);
      labels.push_back(j < k_estimators.size()
                           ? fmt::format("{}: {}", scenes[i].label(), k_estimators[j].label)
                           : fmt::format("{}: reference", scenes[i].label()));
    }
  }
  SheetLayout layout;
  layout.columns = static_cast<int>(k_estimators.size()) + 1;
  layout.label_scale = 1;
  layout.title = fmt::format("Equal time: every estimator after {} s of rendering", budget);
  write_png(dir / "contact_sheet.png", labelled_grid(images, labels, 1, layout));
}

}  // namespace mcrt
