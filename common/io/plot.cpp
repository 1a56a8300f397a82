#include "io/plot.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "io/output.hpp"

namespace mcrt {

namespace fs = std::filesystem;

bool gnuplot_available() {
  static const bool available = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  return available;
}

namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string script_text(const Plot& p) {
  std::ostringstream s;
  s << "# " << p.title << "\n"
    << "# Re-plot with: gnuplot " << p.name << ".gp   (in this folder)\n"
    << "if (!exists(\"png_out\")) png_out = " << quote(p.name + ".png") << "\n"
    << "if (!exists(\"svg_out\")) svg_out = " << quote(p.name + ".svg") << "\n"
    << "set datafile separator ','\n"
    << "set datafile columnheaders\n"  // columns are named: using "n":"rmse"
    << "set title " << quote(p.title) << " noenhanced\n"
    << "set xlabel " << quote(p.x_label) << " noenhanced\n"
    << "set ylabel " << quote(p.y_label) << " noenhanced\n"
    << "set grid\n"
    << "set key top right\n";
  if (p.log_x) s << "set logscale x\nset format x '10^{%T}'\n";
  if (p.log_y) s << "set logscale y\nset format y '10^{%T}'\n";
  s << p.settings << (p.settings.empty() || p.settings.back() == '\n' ? "" : "\n");
  s << "set terminal pngcairo size " << p.width << "," << p.height
    << " enhanced font 'DejaVu Sans,11'\n"
    << "set output png_out\n"
    << p.plot << "\n"
    << "set terminal svg size " << p.width << "," << p.height << " enhanced dynamic\n"
    << "set output svg_out\n"
    << "replot\n"
    << "set output\n";
  return s.str();
}

}  // namespace

PlotResult write_plot(const fs::path& dir, const Plot& plot) {
  write_file_atomic(dir / (plot.name + ".gp"), script_text(plot));
  if (!gnuplot_available()) {
    static bool told = false;
    if (!told)
      std::cerr << "note: gnuplot not found, so no PNG/SVG plots were drawn; the .gp scripts "
                   "and CSV files are written. Install it with: sudo apt-get install gnuplot-nox\n";
    told = true;
    return PlotResult::no_gnuplot;
  }
  const fs::path png = dir / (plot.name + ".png"), svg = dir / (plot.name + ".svg");
  const fs::path png_tmp = temporary_path_for(png), svg_tmp = temporary_path_for(svg);
  const std::string command = "cd " + quote(dir.string()) + " && gnuplot -e \"png_out=" +
                              quote(png_tmp.filename().string()) + "; svg_out=" +
                              quote(svg_tmp.filename().string()) + "\" " +
                              quote(plot.name + ".gp") + " 2>&1";
  std::string messages;
  if (FILE* pipe = ::popen(command.c_str(), "r")) {
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) messages += buffer;
    const int status = ::pclose(pipe);
    if (status == 0 && fs::exists(png_tmp) && fs::exists(svg_tmp)) {
      commit_file(png_tmp, png);
      commit_file(svg_tmp, svg);
      return PlotResult::drawn;
    }
  }
  std::error_code ec;
  fs::remove(png_tmp, ec);
  fs::remove(svg_tmp, ec);
  std::cerr << "warning: gnuplot failed on " << (dir / (plot.name + ".gp")).string() << ":\n"
            << messages;
  return PlotResult::gnuplot_failed;
}

}  // namespace mcrt
