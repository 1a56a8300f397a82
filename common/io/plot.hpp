#pragma once
/// Plots: a gnuplot script written beside its CSV, run to make PNG and SVG. A student can edit
/// the script and re-run `gnuplot NAME.gp` in the output folder: it names its files relative to
/// that folder. Without gnuplot the script and data are kept and the chapter says how to
/// install it.

#include <filesystem>
#include <string>
#include <vector>

namespace mcrt {

struct Plot {
  std::string name;  ///< file stem: NAME.gp, NAME.png, NAME.svg
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
  /// The plot command is several plots on one page (a main plot and an inset): it runs inside
  /// `set multiplot`, once per image instead of `replot` (which redraws only the last plot),
  /// so everything after its first plot must set back what it changes.
  bool multiplot = false;
  /// The values the plot draws on each axis, where a run can make them degenerate (all zero,
  /// one point): a log axis with no positive value is drawn linear, and an axis whose values
  /// are all equal gets a range around them, so gnuplot has nothing to warn about. Empty:
  /// gnuplot's own ranges.
  std::vector<double> x_values = {};
  std::vector<double> y_values = {};
};

/// What happened to the images of a plot.
enum class PlotResult { drawn, no_gnuplot };

/// Writes dir/NAME.gp (atomically) and, when gnuplot is installed, runs `gnuplot NAME.gp` in
/// `dir` (spawned without a shell, so any folder name works) to draw dir/NAME.png and
/// NAME.svg. The images are accepted only if gnuplot exits with 0, reports no error on stderr
/// (a warning is passed on as one line), and both files are complete (image_file_problem);
/// otherwise they are removed and IoError names the file or the script and the reason. A
/// missing gnuplot is reported once on stderr.
/// A chapter writes into its staging folder (app/run_folder.hpp), so a failed plot never
/// reaches --out.
PlotResult write_plot(const std::filesystem::path& dir, const Plot& plot);

/// Why an image gnuplot drew is incomplete, or "" if it is whole: a PNG must start with the
/// PNG signature and end with an IEND chunk, an SVG must end with </svg>.
std::string image_file_problem(const std::filesystem::path& file);

/// Whether gnuplot is on the PATH.
bool gnuplot_available();

/// How long one gnuplot may run before its process group is killed (default 30 s; a chapter
/// takes MCRT_GNUPLOT_TIMEOUT, 1 to 3600 seconds, read strictly by app/cli).
void set_gnuplot_time_limit(int seconds);

}  // namespace mcrt
