#pragma once
// Chapter 07's figures: the variance of one sample for each pdf, in the furnace and in the
// scene, over variance_vs_m.csv (columns by name); the images and the noise strip.

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/plot.hpp"
#include "io/table.hpp"
#include "render/image.hpp"
#include "render/render.hpp"
#include "sampling/cosine_power.hpp"

namespace mcrt {

// variance_vs_m: one x position per pdf (the row number, labelled by the pdf column), the
// measured variances as points and the furnace's closed form as open squares. A log axis has
// no 0: the cosine pdf's furnace variance (0 to rounding) is drawn at the bottom edge, labelled.
inline void write_variance_plot(const std::filesystem::path& out, const std::string& scene,
                                int spp, const Table& variances) {
  const std::string settings =
      "set key top left\nset offsets 0.3, 0.3, 0, 0\nset xtics rotate by -30\n"
      "floor = 1e-6\nset yrange [floor:*]\n"
      "set label 1 'furnace, cosine: 0 (exact)' at first 1.1, first floor * 2.5 left\n"
      "set label 2 'no square: infinite variance (m >= 3)' at graph 0.98, graph 0.05 right\n";
  const auto clamp = [](const char* column) {
    return fmt::format("(column(\"{0}\") > floor ? column(\"{0}\") : floor)", column);
  };
  Plot plot{"variance_vs_m",
            fmt::format("Variance of one sample, per pixel, for each pdf ({} spp x 2 renders)",
                        spp),
            "pdf of the bounce direction", "variance of one sample", false, true, settings,
            fmt::format("plot 'variance_vs_m.csv' using 0:{}:xticlabels(stringcolumn(\"pdf\")) "
                        "with linespoints pt 7 ps 1.5 lw 2 title 'furnace, measured', "
                        "'' using 0:\"furnace_variance_theory\" with points pt 4 ps 2.5 lw 2 "
                        "lc 'black' title 'furnace, closed form', "
                        "'' using 0:{} with linespoints pt 5 ps 1.5 lw 2 title '{}, measured'",
                        clamp("furnace_variance"), clamp("scene_variance"), scene)};
  // Without light every variance is 0: all at the floor, an axis of one value.
  for (const char* column : {"furnace_variance", "furnace_variance_theory", "scene_variance"})
    for (double y : variances.numbers(column)) plot.y_values.push_back(std::max(y, 1e-6));
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
