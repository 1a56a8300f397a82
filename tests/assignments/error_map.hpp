#pragma once
// Where a render disagrees with its reference: the signed z-score of every region, as a text
// grid (always in the test's output, and in results.json) and as a false-colour PNG (blue too
// dark, white agrees, red too bright) written beside the test's reports. The checker computes
// and writes both from the samples the subject produced: nothing here runs student code.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/grading.hpp"
#include "io/image_file.hpp"
#include "io/text.hpp"
#include "render/image.hpp"
#include "stats/hypothesis.hpp"
#include "stats/report.hpp"

namespace mcrt::testing::assignment {

/// The colour scale saturates at |z| = 8, about twice the flagging threshold: noise (|z| < 2)
/// stays near white, a flagged region is clearly coloured, a gross bug is fully red or blue.
inline constexpr double k_error_map_z_scale = 8.0;
/// Pixels per region side in the PNG: room for the region's z printed in it.
inline constexpr int k_error_map_cell = 64;

/// Signed z-scores of a grid of regions, row-major (row 0 at the top), combined over the
/// grading seeds: z = sum_seeds z_seed / sqrt(k_seeds), standard normal per region for a
/// correct solution (the seeds are independent).
struct RegionErrorMap {
  int columns = 0, rows = 0;
  std::vector<double> z;
  std::vector<std::string> column_labels, row_labels;

  double at(int column, int row) const {
    return z[static_cast<std::size_t>(row * columns + column)];
  }
  /// The two-sided per-region threshold at which a correct solution's map flags any of its
  /// regions with probability k_seed_alpha (Sidak over the regions): 4.17 for 16 regions.
  double threshold() const {
    return normal_quantile(1.0 - 0.5 * sidak_alpha(k_seed_alpha, columns * rows));
  }
  bool flagged(int column, int row) const {
    return !(std::abs(at(column, row)) <= threshold());
  }  // NaN flags
};

/// A region test's verdict and where it disagrees (its error map).
struct RegionResult : TaskResult {
  RegionErrorMap map;
};

/// An empty map of columns x rows regions with their labels.
inline RegionErrorMap make_error_map(int columns, int rows, std::vector<std::string> column_labels,
                                     std::vector<std::string> row_labels) {
  return {columns, rows, std::vector<double>(static_cast<std::size_t>(columns * rows), 0.0),
          std::move(column_labels), std::move(row_labels)};
}

/// One region's signed z: (mean - reference) / standard_error. A region with no spread at all
/// (every sample the same, as in a region of sky seen directly) has z = 0 when it agrees and
/// +-inf when it does not; a missing sample (NaN) gives NaN.
inline double region_z(double mean, double reference, double standard_error) {
  const double d = mean - reference;
  if (standard_error > 0.0 || std::isnan(d)) return d / standard_error;
  return d == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), d);
}

/// Adds one seed's region z-scores (in the map's order) to the combined map.
inline void add_seed(RegionErrorMap& map, const std::vector<double>& z) {
  for (std::size_t r = 0; r < map.z.size(); ++r)
    map.z[r] += (r < z.size() ? z[r] : std::nan("")) / std::sqrt(static_cast<double>(k_seeds));
}

/// The map as text: a header line starting "region error map" (scripts/grade keeps that block
/// in a passing test's feedback too), then every line indented.
inline std::string error_map_text(const RegionErrorMap& map) {
  std::string out = fmt::format(
      "region error map: z = (your mean - reference) / standard error per region, the {} seeds combined\n"
      "  (+ too bright, - too dark; ! marks |z| > {:.2f}, which a correct solution reaches in any region once in {:.0f} runs)\n",
      k_seeds, map.threshold(), 1.0 / k_seed_alpha);
  std::size_t label = 0, width = 8;
  for (const std::string& l : map.row_labels) label = std::max(label, l.size());
  for (const std::string& l : map.column_labels) width = std::max(width, l.size());
  out += fmt::format("  {:<{}}", "", label);
  for (int c = 0; c < map.columns; ++c)
    out += fmt::format(" {:>{}} ", map.column_labels[static_cast<std::size_t>(c)], width);
  out += "\n";
  for (int r = 0; r < map.rows; ++r) {
    out += fmt::format("  {:<{}}", map.row_labels[static_cast<std::size_t>(r)], label);
    for (int c = 0; c < map.columns; ++c)
      out += fmt::format(" {:>+{}.1f}{}", map.at(c, r), width, map.flagged(c, r) ? "!" : " ");
    out += "\n";
  }
  return out;
}

/// The diverging colour of z: white at 0, towards red (too bright) or blue (too dark), fully
/// saturated at |z| >= k_error_map_z_scale; NaN is black (no value).
inline Color error_map_color(double z) {
  if (std::isnan(z)) return Color(0.0);
  const double t = std::clamp(z / k_error_map_z_scale, -1.0, 1.0);
  return t >= 0.0 ? Color(1.0, 1.0 - t, 1.0 - t) : Color(1.0 + t, 1.0 + t, 1.0);
}

/// Where error_map_image puts the regions and the colour scale, in pixels.
struct ErrorMapLayout {
  int left = 0, top = 0;             ///< the top-left corner of region (0, 0)
  int bar_top = 0, bar_height = 16;  ///< the colour scale: the grid's width, under it
};

inline ErrorMapLayout error_map_layout(const RegionErrorMap& map) {
  constexpr int margin = 8, scale = 2;
  int label = 0;
  for (const std::string& l : map.row_labels) label = std::max(label, text_width(l, scale));
  ErrorMapLayout layout;
  layout.left = margin + label + margin;
  layout.top = margin + 2 * (text_height(scale) + margin);
  layout.bar_top = layout.top + map.rows * k_error_map_cell + margin;
  return layout;
}

/// The false-colour map: a title, the column labels, each region a k_error_map_cell square
/// with its z printed in it (a ! when flagged), the row labels on the left, and under it the
/// colour scale from -k_error_map_z_scale (too dark) to +k_error_map_z_scale (too bright).
inline Image error_map_image(const RegionErrorMap& map) {
  constexpr int margin = 8, scale = 2;
  const Color ink(0.0), grey(0.5);
  const ErrorMapLayout layout = error_map_layout(map);
  const int left = layout.left, top = layout.top, bar_top = layout.bar_top,
            bar_height = layout.bar_height;
  const int grid_width = map.columns * k_error_map_cell;
  const std::string title = "z = (yours - reference) / s.e.";
  Image image(std::max(left + grid_width + margin, 2 * margin + text_width(title, scale)),
              bar_top + bar_height + 2 * margin + text_height(scale), Color(1.0));
  draw_text(image, margin, margin, title, ink, scale);
  for (int c = 0; c < map.columns; ++c) {
    const std::string& l = map.column_labels[static_cast<std::size_t>(c)];
    draw_text(image, left + c * k_error_map_cell + (k_error_map_cell - text_width(l, 1)) / 2,
              top - margin - text_height(1), l, ink, 1);
  }
  for (int r = 0; r < map.rows; ++r) {
    draw_text(image, margin,
              top + r * k_error_map_cell + (k_error_map_cell - text_height(scale)) / 2,
              map.row_labels[static_cast<std::size_t>(r)], ink, scale);
    for (int c = 0; c < map.columns; ++c) {
      const Color fill = error_map_color(map.at(c, r));
      for (int y = 0; y < k_error_map_cell; ++y)
        for (int x = 0; x < k_error_map_cell; ++x) {
          const bool edge =
              x == 0 || y == 0 || x == k_error_map_cell - 1 || y == k_error_map_cell - 1;
          image.at(left + c * k_error_map_cell + x, top + r * k_error_map_cell + y) =
              edge ? grey : fill;
        }
      const std::string z = fmt::format("{:+.1f}{}", map.at(c, r), map.flagged(c, r) ? "!" : "");
      const int w = text_width(z, 1);
      draw_text(image, left + c * k_error_map_cell + (k_error_map_cell - w) / 2,
                top + r * k_error_map_cell + (k_error_map_cell - text_height(1)) / 2, z,
                std::isnan(map.at(c, r)) ? Color(1.0) : ink, 1);
    }
  }
  // The scale: z from -scale to +scale left to right across the grid's width.
  for (int x = 0; x < grid_width; ++x) {
    const double z = k_error_map_z_scale * (2.0 * (x + 0.5) / grid_width - 1.0);
    for (int y = 0; y < bar_height; ++y) image.at(left + x, bar_top + y) = error_map_color(z);
  }
  const std::string low = fmt::format("{:.0f} dark", -k_error_map_z_scale),
                    high = fmt::format("+{:.0f} bright", k_error_map_z_scale);
  const int label_y = bar_top + bar_height + margin / 2;
  draw_text(image, left, label_y, low, ink, 1);
  draw_text(image, left + (grid_width - text_width("0", 1)) / 2, label_y, "0", ink, 1);
  draw_text(image, left + grid_width - text_width(high, 1), label_y, high, ink, 1);
  return image;
}

/// Writes `name`/error_map.png under the test reports' folder (failure_report_root(): the
/// checker's report folder when graded) and prints the text map and where the image is, so the
/// test's output shows them whether it passes or fails.
inline void report_error_map(const RegionErrorMap& map, const std::string& name) {
  std::cout << error_map_text(map);
  const std::filesystem::path path = failure_report_root() / name / "error_map.png";
  try {
    std::filesystem::create_directories(path.parent_path());
    write_png(path, error_map_image(map));
    std::cout << "  error map image: " << path.string() << "\n";
  } catch (const std::exception& e) {  // the text map above is the guaranteed form
    std::cout << "  error map image: not written (" << e.what() << ")\n";
  }
  std::cout.flush();
}

}  // namespace mcrt::testing::assignment
