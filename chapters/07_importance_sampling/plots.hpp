#pragma once
// Chapter 07's figures: the variance of one sample for each pdf, in the furnace and in the
// scene, over variance_vs_m.csv (columns by name); the images and the noise strip.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/plot.hpp"
#include "io/table.hpp"
#include "render/path_tracer.hpp"
#include "render/image.hpp"
#include "render/render.hpp"
#include "sampling/cosine_power.hpp"

namespace mcrt {

// variance_curve.csv: the furnace's closed-form variance of one sample for p_m ~ cos^m at real
// m in [0, 3), denser towards 3 where it diverges: b = E[w^2] = 4a^2 / ((m + 1)(3 - m)) (the
// cos^m row of common/render/importance_path_tracer.hpp, which holds for any real m > -1).
inline Table variance_curve(double albedo, double emission, int depth) {
  Table curve({{"m", Column::real, 9}, {"furnace_variance_theory", Column::real, 9}});
  constexpr int k_points = 400;
  for (int i = 0; i < k_points; ++i) {
    // Half the points evenly over [0, 2.5], half over 3 - m from 0.5 down to 1e-3 geometrically.
    const double t = static_cast<double>(i) / (k_points / 2);
    const double m = i < k_points / 2 ? 2.5 * t : 3.0 - 0.5 * std::pow(1e-3 / 0.5, t - 1.0);
    const double b = 4.0 * albedo * albedo / ((m + 1.0) * (3.0 - m));
    curve.add_row({m, furnace_radiance_variance_from_moments(albedo, b, emission, depth)});
  }
  return curve;
}

// variance_vs_m: the variance of one sample against m on a continuous axis, p_m ~ cos^m. The
// furnace's closed form is a curve with its asymptote at m = 3; the measured variances of both
// scenes are points at their m. At m >= 3 the variance is infinite in both (the weight
// cos / p_m ~ cos^(1 - m) at the horizon): no point is drawn there, only an arrow up. The
// cosine pdf's furnace variance is 0 (exact), which a log axis cannot show: its point is left
// out and an arrow down marks it. The grazing pdf is no cos^m: its closed form is a level
// line. An inset draws each p_m(theta) against cos(theta)/pi, the shape of the integrand.
inline void write_variance_plot(const std::filesystem::path& out, const std::string& scene, int spp,
                                const Table& variances, double albedo, double emission, int depth) {
  write_csv(out / "variance_curve.csv", variance_curve(albedo, emission, depth));
  std::vector<int> powers;  // of the cos^m rows
  double highest = 0.0, lowest = HUGE_VAL, grazing = std::nan("");
  for (std::size_t i = 0; i < variances.size(); ++i) {
    if (variances.at(i, "pdf").string() == "grazing") {
      grazing = variances.at(i, "furnace_variance_theory").number();
      continue;
    }
    const int m = static_cast<int>(variances.at(i, "m").number());
    powers.push_back(m);
    if (m >= 3) continue;
    for (const char* column : {"furnace_variance", "scene_variance", "furnace_variance_theory"}) {
      const double v = variances.at(i, column).number();
      if (std::isfinite(v) && v > 0.0) highest = std::max(highest, v), lowest = std::min(lowest, v);
    }
  }
  if (std::isfinite(grazing) && grazing > 0.0)
    highest = std::max(highest, grazing), lowest = std::min(lowest, grazing);
  const bool lit = highest > 0.0;  // without light every variance is 0, none infinite
  if (!lit) highest = 1.0, lowest = 1.0;
  const double y_low = lowest / 10.0, y_high = highest * 30.0;
  const double m_high = std::max(4.0, static_cast<double>(powers.back())) + 1.0;

  std::string main = fmt::format(
      "set origin 0, 0\nset size 1, 1\n"
      "set title 'Variance of one sample against m, p_m ~ cos^m ({} spp x 2 renders)' "
      "noenhanced\n"
      "set xlabel 'm' noenhanced offset 0, 0.3\nset ylabel 'variance of one sample' noenhanced\n"
      "set bmargin 7\n"  // room for the key below the m label
      "set xrange [0:{:.9g}]\nset yrange [{:.9g}:{:.9g}]\nset xtics 1\nset ytics auto\n"
      "set logscale y\nset format y '10^{{%T}}'\nset grid\nset key outside below center horizontal maxrows 2 font ',10'\n"
      "{}",
      spp, m_high, y_low, y_high,
      lit ? "set object 1 rect from first 3, graph 0 to graph 1, graph 1 fc rgb '#e8e8e8' "
            "fs solid noborder behind\n"
            "set arrow 1 from first 3, graph 0 to first 3, graph 1 nohead dt 2 lw 2 lc 'black'\n"
            "set label 1 'm >= 3: infinite variance' at first 3.15, graph 0.06 left noenhanced\n"
          : "");
  int tag = 2;
  for (int m : powers) {
    if (m == 1)  // the cosine pdf: 0 in the furnace, below every log axis
      main += fmt::format(
          "set arrow {0} from first 1, graph 0.16 to first 1, graph 0 head filled lw 2 "
          "lc rgb '#1f77b4'\nset label {0} 'furnace: 0 (exact)' at first 1.08, graph 0.12 left "
          "noenhanced tc rgb '#1f77b4'\n",
          tag++);
    if (m >= 3 && lit)
      main += fmt::format(
          "set arrow {0} from first {1}, graph 0.72 to first {1}, graph 0.97 head filled lw 2 "
          "lc 'black'\nset label {0} 'cos^{1}: infinite variance' at first {1}, graph 0.68 center "
          "noenhanced\n",
          tag++, m);
  }
  // Measured points only where the variance is finite (m < 3), and not 0 on the log axis.
  const auto measured = [](const char* column) {
    return fmt::format(
        "'variance_vs_m.csv' using (column(\"m\") < 3 ? column(\"m\") : NaN):"
        "(column(\"{0}\") > 0 ? column(\"{0}\") : NaN)",
        column);
  };
  main += fmt::format(
      "plot 'variance_curve.csv' using \"m\":\"furnace_variance_theory\" with lines lw 2 "
      "lc rgb '#1f77b4' title 'furnace, closed form', {} with points pt 7 ps 1.8 "
      "lc rgb '#1f77b4' title 'furnace, measured', {} with points pt 5 ps 1.8 lc rgb '#d62728' "
      "title '{}, measured'{}\n",
      measured("furnace_variance"), measured("scene_variance"), scene,
      std::isfinite(grazing) && grazing > 0.0
          ? fmt::format(", {:.9g} with lines dt 3 lw 2 lc rgb '#2ca02c' title 'grazing pdf (not "
                        "a cos^m): furnace closed form'",
                        grazing)
          : std::string());
  // The inset: over theta in [0, pi/2], p_m for every m measured, and cos / pi dashed.
  const std::string inset = fmt::format(
      "unset object 1\nunset arrow\nunset label\nunset logscale y\nset format y '%g'\n"
      "set origin 0.5, 0.27\nset size 0.47, 0.42\n"
      "set title 'the pdfs p_m(theta) against cos(theta) / pi' noenhanced\n"
      "set xlabel 'theta (degrees)' noenhanced offset 0, 0\nset ylabel ''\nset bmargin -1\n"
      "set xrange [0:90]\nset yrange [0:*]\nset xtics 30\nset ytics 0.5\n"
      "set key inside top right vertical maxrows auto font ',9'\n"
      "ms = '{}'\n"
      "plot for [m in ms] (m + 1) / (2 * pi) * cos(x * pi / 180)**m with lines lw 2 "
      "title 'p_{{'.m.'}}', cos(x * pi / 180) / pi with lines dt 2 lw 3 lc 'black' "
      "title 'cos / pi'",
      fmt::join(powers, " "));
  Plot plot{"variance_vs_m",
            "Variance of one sample against m",
            "m",
            "variance of one sample",
            false,
            true,
            "",
            main + inset};
  plot.width = 1000;
  plot.height = 650;
  plot.multiplot = true;
  plot.y_values = {y_low, y_high};
  write_plot(out, plot);
}

// The compared images (uniform, cosine, cosine at equal time, reference) as PNG and PFM, and
// the noise strip: the centre of each pdf's
// scene render (in the order of pdfs) beside the reference's, and below them the same centres
// as 8x8 block means, where the sparse bright pixels' light shows as brightness.
inline void write_images(const std::filesystem::path& out, const std::vector<HemispherePdf>& pdfs,
                         const std::vector<RenderResult>& scene, const Image& cosine_equal_time,
                         const Image& reference, int spp) {
  const auto write = [&](const std::string& stem, const Image& image) {
    write_png(out / (stem + ".png"), image);
    write_pfm(out / (stem + ".pfm"), image);
  };
  write("uniform", scene[0].image);  // the pdfs start with m = 0, 1
  write("cosine", scene[1].image);
  write("cosine_equal_time", cosine_equal_time);
  write("reference", reference);
  std::vector<Image> strip;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < pdfs.size(); ++i) {
    strip.push_back(scene[i].image);
    labels.push_back(pdf_name(pdfs[i]));
  }
  strip.push_back(reference);
  labels.push_back("reference");
  write_png(out / "noise_strip.png",
            centre_detail_strip(strip, labels, fmt::format("at {} spp per pdf", spp), 8));
}

}  // namespace mcrt
