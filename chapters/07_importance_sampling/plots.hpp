#pragma once
// Chapter 07's figure: the variance of one sample for each pdf, in the furnace and in the
// scene, over variance_vs_m.csv (columns by name).

#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "io/plot.hpp"

namespace mcrt {

// variance_vs_m: one x position per pdf (the row number, labelled by the pdf column), the
// measured variances as points and the furnace's closed form as open squares. A log axis has
// no 0: the cosine pdf's furnace variance (0 to rounding) is drawn at the bottom edge, labelled.
inline void write_variance_plot(const std::filesystem::path& out, const std::string& scene,
                                int spp) {
  const std::string settings =
      "set key top left\nset offsets 0.3, 0.3, 0, 0\nset xtics rotate by -30\n"
      "floor = 1e-6\nset yrange [floor:*]\n"
      "set label 1 'furnace, cosine: 0 (exact)' at first 1.1, first floor * 2.5 left\n"
      "set label 2 'no square: infinite variance (m >= 3)' at graph 0.98, graph 0.05 right\n";
  const auto clamp = [](const char* column) {
    return fmt::format("(column(\"{0}\") > floor ? column(\"{0}\") : floor)", column);
  };
  write_plot(out,
             {"variance_vs_m",
              fmt::format("Variance of one sample, per pixel, for each pdf ({} spp x 2 renders)",
                          spp),
              "pdf of the bounce direction", "variance of one sample", false, true, settings,
              fmt::format("plot 'variance_vs_m.csv' using 0:{}:xticlabels(stringcolumn(\"pdf\")) "
                          "with linespoints pt 7 ps 1.5 lw 2 title 'furnace, measured', "
                          "'' using 0:\"furnace_variance_theory\" with points pt 4 ps 2.5 lw 2 "
                          "lc 'black' title 'furnace, closed form', "
                          "'' using 0:{} with linespoints pt 5 ps 1.5 lw 2 title '{}, measured'",
                          clamp("furnace_variance"), clamp("scene_variance"), scene)});
}

}  // namespace mcrt
