#pragma once
/// Plots: a gnuplot script written beside its CSV, run to make PNG and SVG. A student can edit
/// the script and re-run `gnuplot NAME.gp` in the output folder. Without gnuplot the script
/// and data are kept and the chapter says how to install it.

#include <filesystem>
#include <string>

namespace mcrt {

struct Plot {
  std::string name;      ///< file stem: NAME.gp, NAME.png, NAME.svg
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::string settings;  ///< extra gnuplot lines before the plot (ranges, keys, labels)
  /// The plot command. The CSV's first row names the columns, and plots use the names:
  /// plot 'errors.csv' using "n":"rmse" with lines
  std::string plot;
  int width = 900;
  int height = 600;
};

/// What happened to the images of a plot.
enum class PlotResult { drawn, no_gnuplot, gnuplot_failed };

/// Writes dir/NAME.gp (atomically) and, when gnuplot is installed, dir/NAME.png and NAME.svg
/// (each made under a temporary name, then renamed). Throws IoError if the script cannot be
/// written; reports a missing or failing gnuplot once on stderr.
PlotResult write_plot(const std::filesystem::path& dir, const Plot& plot);

/// Whether gnuplot is on the PATH.
bool gnuplot_available();

}  // namespace mcrt
