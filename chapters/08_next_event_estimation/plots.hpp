#pragma once
// Chapter 08's figures: log relative MSE against log rays per scene (efficiency.csv, columns by
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

// relmse_vs_rays_<scene>.png: one line per estimator, and a line of slope -1 through the
// lowest relMSE x rays of NEE (an unbiased estimator's relMSE falls as 1 / rays). The axis
// ends where the runs do, often within a decade: tics at 1, 2, 5 times the powers of 10.
inline void write_relmse_plot(const std::filesystem::path& dir, const ShootoutScene& s) {
  std::string plot = "plot ";
  const std::string this_scene =
      fmt::format("strcol(\"scene\") eq \"{}\" && abs(column(\"light_scale\") - {}) < 1e-9",
                  s.scene, s.light_scale);
  for (const EstimatorInfo& e : k_estimators)
    plot += fmt::format(
        "'efficiency.csv' using ({} && strcol(\"estimator\") eq \"{}\" ? "
        "column(\"rays_per_pixel\") : 1/0):\"rel_mse\" with linespoints pt 7 lw 2 title '{}', ",
        this_scene, e.name, e.label);
  plot += "c / x with lines dt 2 lc 'black' title 'slope -1'";
  const std::string settings = fmt::format(
      "set key outside right\nset autoscale xfix\nset format x '%g'\n"
      "set xtics add (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000)\n"
      "stats 'efficiency.csv' using ({} && strcol(\"estimator\") eq \"nee\" ? "
      "column(\"rel_mse\") * column(\"rays_per_pixel\") : 1/0) nooutput\nc = STATS_min\n",
      this_scene);
  write_plot(dir, {fmt::format("relmse_vs_rays_{}", s.slug()),
                   fmt::format("Relative MSE against rays traced: {}", s.label()), "rays per pixel",
                   "relative MSE", true, true, settings, plot, 1000, 600});
}

// contact_sheet.png: one row per scene, one column per estimator plus the reference, the images
// of the largest budget. The furnace's radiance, Le / (1 - a), is above 1 and would show as
// white panels: its row is scaled so that the exact value is mid-grey, which shows its noise.
inline void write_contact_sheet(const std::filesystem::path& dir,
                                const std::vector<ShootoutScene>& scenes, const Shootout& result,
                                int budget) {
  std::vector<Image> images;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const std::vector<Image>& row = result.equal_rays[i];
    const bool furnace = scenes[i].scene == "furnace";
    const double exact = mean_radiance(row.back());
    const double exposure = furnace && exact > 0.0 ? 0.5 / exact : 1.0;
    const std::string name =
        furnace ? fmt::format("furnace (x{:.2g})", exposure) : scenes[i].label();
    for (std::size_t j = 0; j < row.size(); ++j) {
      Image shown = row[j];
      for (Color& c : shown.pixels) c *= exposure;
      images.push_back(std::move(shown));
      labels.push_back(j < k_estimators.size() ? fmt::format("{}: {}", name, k_estimators[j].label)
                                               : fmt::format("{}: reference", name));
    }
  }
  SheetLayout layout;
  layout.columns = static_cast<int>(k_estimators.size()) + 1;
  layout.label_scale = 1;
  layout.title = fmt::format("Equal rays: every estimator after {} rays per pixel", budget);
  write_png(dir / "contact_sheet.png", labelled_grid(images, labels, 1, layout));
}

}  // namespace mcrt
