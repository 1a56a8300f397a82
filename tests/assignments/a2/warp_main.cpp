// a2_warp: the warp tests of assignment a2, to run and look at while writing the samplers.
// For each sampler (a2.1-a2.5) it draws the points the chi-square test draws, writes their
// point cloud and the heat map of observed / expected counts per cell of the test's binning,
// and prints the test's p-value at --seed. A sampler not written yet is named and skipped.
//
//   cmake --build build -j2 --target a2_warp && build/bin/a2_warp
//   -> out/a2_warp/<sampler>_points.png, <sampler>_ratio.png

#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "assignments/a2/warp.hpp"
#include "io/image_file.hpp"
#include "sampling/cone.hpp"
#include "sampling/hemisphere.hpp"
#include "sampling/plane.hpp"
#include "sampling/sphere.hpp"

using namespace mcrt;
using namespace mcrt::testing;
using namespace mcrt::testing::assignment;

namespace {

const Chapter k_chapter{
    "a2_warp",
    "Assignment a2's warp tests: for each of your samplers, the point cloud and the heat map of "
    "observed / expected counts over the chi-square test's cells (white: as expected; red: too many "
    "points; blue: too few), and the test's p-value."};

struct Options {
  CommonOptions common;
  std::uint64_t samples = k_sampler_samples;  // points per sampler, as the graded test draws
};

constexpr int k_cell_pixels = 24;                         // one chi-square cell of the heat map
constexpr int k_cloud_width = 504, k_cloud_height = 264;  // the (phi, cos theta) rectangle
constexpr int k_disk_size = 400;

/// A sampler, as the student wrote it, in bulk (what run_warp takes).
template <class F>
auto directions(F f) {
  return [f](const std::vector<Vec2>& u) {
    std::vector<Vec3> out;
    out.reserve(u.size());
    for (const Vec2& x : u) out.push_back(f(x));
    return out;
  };
}
template <class F>
auto densities(F f) {
  return [f](const auto& points) {
    std::vector<double> out;
    out.reserve(points.size());
    for (const auto& p : points) out.push_back(f(p));
    return out;
  };
}

/// One sampler's warp test: writes its two images, prints its line.
template <class Point, class SampleBatch, class PdfBatch>
void warp_one(const Options& o, const std::string& task, const std::string& name,
              SampleBatch&& sample, PdfBatch&& pdf, const Binning<Point>& binning, int cloud_width,
              int cloud_height) {
  try {
    const WarpResult<Point> w = run_warp(sample, pdf, binning, o.common.seed, o.samples);
    write_png(o.common.dir / (name + "_points.png"),
              point_cloud(w.points, binning, cloud_width, cloud_height));
    write_png(o.common.dir / (name + "_ratio.png"),
              ratio_heat_map(w.chi_square, binning, k_cell_pixels));
    if (!o.common.quiet)
      fmt::print("{:5} {:20} p = {:<10.3g} {}  {}\n", task, name, w.chi_square.p_value,
                 w.chi_square.p_value < k_seed_alpha ? "REJECTED" : "ok      ",
                 w.chi_square.describe());
  } catch (const std::logic_error& e) {  // a stub of the kit: "not implemented: a2.N ..."
    if (!o.common.quiet) fmt::print("{:5} {:20} skipped: {}\n", task, name, e.what());
  }
}

void run(const Options& o) {
  if (!o.common.quiet)
    fmt::print(
        "a2_warp  seed {}  {} points per sampler; the test rejects at p < {} (a grading seed fails it)\n",
        o.common.seed, o.samples, k_seed_alpha);
  const double cos_max = k_a2_cone_cos_theta_max;
  warp_one<Vec3>(o, "a2.1", "uniform_hemisphere", directions(sample_uniform_hemisphere),
                 densities([](const Vec3&) { return uniform_hemisphere_pdf(); }),
                 sampler_hemisphere_binning(), k_cloud_width, k_cloud_height);
  warp_one<Vec3>(o, "a2.2", "cosine_hemisphere", directions(sample_cosine_hemisphere),
                 densities([](const Vec3& w) { return cosine_hemisphere_pdf(w.z); }),
                 sampler_hemisphere_binning(), k_cloud_width, k_cloud_height);
  warp_one<Vec3>(o, "a2.3", "uniform_sphere", directions(sample_uniform_sphere),
                 densities([](const Vec3&) { return uniform_sphere_pdf(); }),
                 sphere_binning(21, 21), k_cloud_width, k_cloud_width / 2);
  warp_one<Vec2>(
      o, "a2.4", "unit_disk",
      [](const std::vector<Vec2>& u) {
        std::vector<Vec2> out;
        out.reserve(u.size());
        for (const Vec2& x : u) out.push_back(sample_uniform_disk(x));
        return out;
      },
      densities([](const Vec2&) { return uniform_disk_pdf(); }), sampler_disk_binning(),
      k_disk_size, k_disk_size);
  warp_one<Vec3>(o, "a2.5", "uniform_cone",
                 directions([cos_max](Vec2 u) { return sample_uniform_cone(u, cos_max); }),
                 densities([cos_max](const Vec3& w) { return uniform_cone_pdf(w.z, cos_max); }),
                 sampler_cone_binning(), k_cloud_width, k_cloud_height);
  if (!o.common.quiet)
    fmt::print("wrote {}/<sampler>_points.png and <sampler>_ratio.png\n", o.common.out.string());
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_number_option(app, "--samples", o.samples,
                    "points per sampler (the graded test draws 100000)", 1000, 10'000'000);
  return app.run(argc, argv, [&] { run(o); });
}
