#pragma once
// Warp tests a student runs and reads (a2_warp, warp_main.cpp): each of a2's samplers drawn as
// a point cloud and as a heat map of observed / expected counts over the very cells the
// chi-square test of a2_test.cpp uses, with that test's p-value. A right sampler gives an even
// cloud (in the equal-area picture, a uniform one looks uniform) and a white heat map; a wrong
// one shows where it is wrong: red cells where it puts too many points, blue where too few.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "assignments/a2/a2_checks.hpp"
#include "core/rng.hpp"
#include "render/image.hpp"
#include "stats/binning.hpp"
#include "stats/chi_square.hpp"

namespace mcrt::testing::assignment {

/// The heat map's colour scale saturates at this ratio (and its inverse): 4x too many points
/// is full red, 4x too few full blue; a correct sampler's cells stay within 1 +- 0.2 or so.
inline constexpr double k_warp_ratio_saturation = 4.0;

/// Linear RGB of observed / expected = ratio: white at 1, towards red above, towards blue
/// below, by log(ratio) / log(saturation) so that 2x too many and 2x too few look alike.
inline Color ratio_colour(double ratio) {
  const double t =
      std::clamp(std::log(std::max(ratio, 1e-12)) / std::log(k_warp_ratio_saturation), -1.0, 1.0);
  return t >= 0.0 ? Color(1.0, 1.0 - t, 1.0 - t) : Color(1.0 + t, 1.0 + t, 1.0);
}

/// The ratio a colour of ratio_colour stands for (clamped to the scale's ends): how a test or a
/// tool reads the heat map back.
inline double ratio_of_colour(const Color& c) {
  const double t = c.b >= c.r ? -(1.0 - c.r) : 1.0 - c.g;
  return std::pow(k_warp_ratio_saturation, t);
}

/// Cells with no expected point (outside the pdf's support) are drawn grey when empty and black
/// when a point landed there: the sampler put a point where its pdf says none can go.
inline const Color k_warp_empty_cell{0.5, 0.5, 0.5};
inline const Color k_warp_impossible_cell{0.0, 0.0, 0.0};

/// One sampler's warp test: its points and their chi-square test against its pdf.
template <class Point>
struct WarpResult {
  std::vector<Point> points;
  ChiSquareResult chi_square;
};

/// Draws `samples` points with `sample` (a bulk producer, vector of u -> vector of Point) from
/// u of Rng(seed, 41), the grading's stream (sampler_chi_square), and tests them against the cell
/// probabilities of `pdf` (a bulk pdf) in `binning`: at a grading seed (1009, 2029, 3037) and
/// 1e5 samples, the p-value is the one a2_test.cpp computes at that seed.
template <class Point, class SampleBatch, class PdfBatch>
WarpResult<Point> run_warp(SampleBatch&& sample, PdfBatch&& pdf, const Binning<Point>& binning,
                           std::uint64_t seed, std::uint64_t samples) {
  Rng rng(seed, 41);
  std::vector<Vec2> u(samples);
  for (Vec2& x : u) x = rng.uniform2();
  WarpResult<Point> result;
  result.points = sample(u);
  result.chi_square =
      chi_square_points_test(result.points, bulk_cell_probabilities(pdf, binning), binning);
  return result;
}

/// The heat map of observed / expected per cell of `grid`, `cell_pixels` square per cell: u
/// (phi, or r^2 for the disk) across, v (cos theta, z, or phi for the disk) up, so the pole of
/// a hemisphere is the top row.
inline Image ratio_heat_map(const ChiSquareResult& r, const Grid& grid, int cell_pixels) {
  Image image(grid.u_cells * cell_pixels, grid.v_cells * cell_pixels);
  for (const CellCount& c : r.cells) {
    const Color colour = c.expected > k_zero_expected ? ratio_colour(c.observed / c.expected)
                         : c.observed > 0.0           ? k_warp_impossible_cell
                                                      : k_warp_empty_cell;
    const int x0 = c.u_index * cell_pixels, y0 = (grid.v_cells - 1 - c.v_index) * cell_pixels;
    for (int y = y0; y < y0 + cell_pixels; ++y)
      for (int x = x0; x < x0 + cell_pixels; ++x) image.at(x, y) = colour;
  }
  return image;
}

/// The pixel of the heat map at the centre of cell (u_index, v_index).
inline std::pair<int, int> heat_map_pixel(const Grid& grid, int cell_pixels, int u_index,
                                          int v_index) {
  return {u_index * cell_pixels + cell_pixels / 2,
          (grid.v_cells - 1 - v_index) * cell_pixels + cell_pixels / 2};
}

/// The point cloud: a disk's points as they are (x across, y up, on [-1, 1]^2); directions at
/// their (u, v) parameters of the binning, an equal-area map (phi across, cos theta or z up), so
/// the shade of a region is its density per steradian. Each pixel's shade is 1 - exp(-n / n0)
/// for n points in it, n0 twice the mean count of the pixels the domain covers: grey where
/// the density is as average, white where it crowds, black where no point falls.
template <class Point>
Image point_cloud(const std::vector<Point>& points, const Binning<Point>& binning, int width,
                  int height) {
  std::vector<double> count(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  double covered = static_cast<double>(count.size());
  for (const Point& p : points) {
    double x = 0.0, y = 0.0;  // in [0, 1)
    if constexpr (std::is_same_v<Point, Vec2>) {
      x = 0.5 * (p.x + 1.0);
      y = 0.5 * (p.y + 1.0);
      covered = static_cast<double>(count.size()) * k_pi / 4.0;  // the disk inside the square
    } else {
      const std::optional<Vec2> uv = binning.parameters_of(p);
      if (!uv) continue;  // outside the domain: the heat map and the p-value say so
      x = (uv->x - binning.u_min) / (binning.u_max - binning.u_min);
      y = (uv->y - binning.v_min) / (binning.v_max - binning.v_min);
    }
    if (!(x >= 0.0 && x <= 1.0 && y >= 0.0 && y <= 1.0)) continue;
    const int i = std::min(static_cast<int>(x * width), width - 1);
    const int j = std::min(static_cast<int>((1.0 - y) * height), height - 1);  // row 0 at the top
    count[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
          static_cast<std::size_t>(i)] += 1.0;
  }
  const double n0 = 2.0 * static_cast<double>(std::max<std::size_t>(points.size(), 1)) / covered;
  Image image(width, height);
  for (std::size_t k = 0; k < count.size(); ++k)
    image.pixels[k] = Color(1.0 - std::exp(-count[k] / n0));
  return image;
}

}  // namespace mcrt::testing::assignment
