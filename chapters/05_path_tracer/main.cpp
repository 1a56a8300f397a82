// Chapter 05: the noisy path tracer.
//
//   for each sample:
//     shoot a ray into the scene
//     repeat until the path leaves the scene or has bounced --depth times:
//       find the closest intersection
//       add its emitted light, times the path weight
//       pick one new direction uniformly on the hemisphere
//       multiply the weight by f_r cos(theta) / pdf
//     set the sample colour to the sum
//
// One branch per bounce (chapter 04 with N = 1): no exponential growth, so all the work goes
// into samples per pixel. The images are unbiased but noisy, and the noise falls as spp^-1/2.
// The error of each image is estimated without a reference, from two independent renders A and
// B at the same spp: E[(A - B)^2] / 2 = Var[A] = the mean squared error of A.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "integration/statistics.hpp"
#include "io/cli.hpp"
#include "io/contact_sheet.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "io/summary.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

using namespace mcrt;

namespace {

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{256, 192};
  std::vector<int> spp{1, 4, 16, 64, 256};  // samples per pixel of each image
  int depth = 10;                           // bounces after the camera ray's hit
};

// The most rays one run may trace: about 1.4 hours at 2e7 rays per second.
constexpr double k_max_rays = 1e11;

// One row of rmse_vs_spp.csv: the image at `spp` and its error.
struct SppRow {
  int spp = 0;
  double rmse = 0.0;     // sqrt(mean over pixels and channels of (A - B)^2 / 2)
  double seconds = 0.0;  // both renders, A and B
  std::uint64_t rays = 0;
  std::uint64_t non_finite_samples = 0;
  double rays_per_second() const { return seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0; }
};

template <class... Args>
std::string format(const char* pattern, Args... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, args...);
  return buffer;
}

// The most rays the run can trace: two renders per spp, at most depth + 1 rays per sample.
double max_rays(const Options& o) {
  double samples = 0.0;
  for (int spp : o.spp) samples += 2.0 * spp;
  return samples * o.image.width * o.image.height * (o.depth + 1.0);
}

// Mean squared error of A from two independent renders: mean over pixels and channels of
// (A - B)^2 / 2, since E[(A - B)^2] = Var[A] + Var[B] = 2 Var[A] for unbiased A, B.
double mean_squared_error(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const Color d = a.pixels[i] - b.pixels[i];
    sum += glm::dot(d, d) / 2.0;
  }
  return sum / (3.0 * static_cast<double>(a.pixels.size()));
}

// The same detail of every image, blown up, side by side and labelled.
Image noise_strip(const std::vector<Image>& images, const std::vector<int>& spp) {
  const int width = images.front().width, height = images.front().height;
  const int side = std::max(1, std::min(width, height) / 3);
  const int x = (width - side) / 2, y = (height - side) / 2;  // the centre of the image
  const int factor = std::max(1, 128 / side);
  std::vector<Image> details;
  for (const Image& image : images) details.push_back(upscale_nearest(crop(image, x, y, side, side), factor));
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < details.size(); ++i)
    cells.push_back({&details[i], format("%d spp", spp[i])});
  SheetLayout layout;
  layout.columns = static_cast<int>(cells.size());
  layout.title = format("the image centre (%dx%d pixels, x%d) at growing spp", side, side, factor);
  return make_contact_sheet(cells, layout);
}

void write_csv(const Options& o, const std::vector<SppRow>& rows) {
  std::string csv = "spp,rmse,seconds,rays,rays_per_second\n";
  for (const SppRow& r : rows)
    csv += format("%d,%.9g,%.6g,%llu,%.6g\n", r.spp, r.rmse, r.seconds,
                  static_cast<unsigned long long>(r.rays), r.rays_per_second());
  write_file_atomic(o.common.out / "rmse_vs_spp.csv", csv);
}

void write_rmse_plot(const Options& o, const std::vector<SppRow>& rows, double slope) {
  // The reference line of slope -1/2 passes through the first point.
  const std::string settings =
      format("rmse1 = %.9g\nspp1 = %d\nset key top right\n", rows.front().rmse, rows.front().spp) +
      (std::isfinite(slope) ? format("set label 1 'fitted slope %.3f (theory -0.5)' at graph 0.05, "
                                     "graph 0.1\n", slope)
                            : std::string());
  write_plot(o.common.out,
             {"rmse_vs_spp", "RMS error against samples per pixel (two-render estimate)",
              "samples per pixel", "RMS error", true, true, settings,
              "plot 'rmse_vs_spp.csv' using 1:2 with linespoints pt 7 lw 2 title 'RMS error', "
              "rmse1 * (x / spp1)**-0.5 with lines dt 2 lc 'black' title 'slope -1/2'"});
}

int run(const CLI::App& app, Options o) {
  check_image_size(o.image);
  std::sort(o.spp.begin(), o.spp.end());
  o.spp.erase(std::unique(o.spp.begin(), o.spp.end()), o.spp.end());
  if (max_rays(o) > k_max_rays)
    throw UsageError(format("--spp, --depth, --width, --height: up to %.3g rays (2 renders x "
                            "sum of spp x pixels x (depth + 1)) is above the limit of %.3g",
                            max_rays(o), k_max_rays));
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  prepare_output_dir(o.common.out);

  // Two independent renders per spp: A takes samples [0, spp), B takes [spp, 2 spp). The A
  // images share their first samples, so they show one image converging.
  std::vector<SppRow> rows;
  std::vector<Image> images;
  std::uint64_t rays = 0, non_finite = 0;
  double seconds = 0.0;
  for (int spp : o.spp) {
    ProgressBar progress(format("ch05 %4d spp", spp), 2ull * o.image.height, o.common.quiet);
    auto path_radiance = [&](const Ray& ray, Rng& rng, RayCount& count) {
      return estimate_path_radiance(scene, ray, o.depth, rng, count);
    };
    const RenderResult a = render(camera, {spp, 0, o.common.seed, o.common.threads, &progress},
                                  path_radiance);
    const RenderResult b =
        render(camera, {spp, static_cast<std::uint64_t>(spp), o.common.seed, o.common.threads,
                        &progress},
               path_radiance);
    progress.finish();

    SppRow row;
    row.spp = spp;
    row.rmse = std::sqrt(mean_squared_error(a.image, b.image));
    row.seconds = a.seconds + b.seconds;
    row.rays = a.rays + b.rays;
    row.non_finite_samples = a.non_finite_samples + b.non_finite_samples;
    rows.push_back(row);
    rays += row.rays;
    seconds += row.seconds;
    non_finite += row.non_finite_samples;

    const std::string stem = format("spp_%04d", spp);
    write_png(o.common.out / (stem + ".png"), a.image);
    write_pfm(o.common.out / (stem + ".pfm"), a.image);
    images.push_back(a.image);
  }
  write_png(o.common.out / "noise_strip.png", noise_strip(images, o.spp));

  std::vector<double> spp_values, rmse_values;
  for (const SppRow& r : rows) {
    spp_values.push_back(r.spp);
    rmse_values.push_back(r.rmse);
  }
  const bool can_fit = rows.size() >= 2 && std::all_of(rows.begin(), rows.end(),
                                                        [](const SppRow& r) { return r.rmse > 0.0; });
  const double slope = can_fit ? fit_log_log(spp_values, rmse_values).slope : std::nan("");
  write_csv(o, rows);
  write_rmse_plot(o, rows, slope);

  const double rays_per_second = seconds > 0.0 ? static_cast<double>(rays) / seconds : 0.0;
  Json summary;
  summary["chapter"] = "ch05_path_tracer";
  summary["scene"] = o.scene.scene;
  summary["width"] = o.image.width;
  summary["height"] = o.image.height;
  summary["spp"] = o.spp;
  summary["depth"] = o.depth;
  summary["seed"] = o.common.seed;
  summary["threads"] = o.common.threads;
  summary["rays"] = rays;
  summary["seconds"] = seconds;
  summary["rays_per_second"] = rays_per_second;
  summary["non_finite_samples"] = non_finite;
  summary["rmse_slope"] = can_fit ? Json(slope) : Json(nullptr);  // null: fewer than 2 spp
  summary["rmse_slope_theory"] = -0.5;
  summary["mean_radiance"] = mean_radiance(images.back());
  Json table = Json::array();
  for (const SppRow& r : rows)
    table.push_back({{"spp", r.spp}, {"rmse", r.rmse}, {"seconds", r.seconds}, {"rays", r.rays},
                     {"rays_per_second", r.rays_per_second()},
                     {"non_finite_samples", r.non_finite_samples}});
  summary["rmse_vs_spp"] = table;
  summary["flags"] = flags_json(app);
  write_json(o.common.out / "summary.json", summary);

  if (!o.common.quiet) {
    std::printf("ch05_path_tracer  scene %s  %dx%d  depth %d  %d threads\n",
                o.scene.scene.c_str(), o.image.width, o.image.height, o.depth, o.common.threads);
    std::printf("  %6s  %12s  %12s  %9s  %14s\n", "spp", "RMS error", "x sqrt(spp)", "seconds",
                "rays/s");
    for (const SppRow& r : rows)
      std::printf("  %6d  %12.5g  %12.5g  %9.3f  %14.4g\n", r.spp, r.rmse,
                  r.rmse * std::sqrt(static_cast<double>(r.spp)), r.seconds,
                  r.rays_per_second());
    if (can_fit)
      std::printf("  fitted slope of log RMS error against log spp: %.3f (theory -0.5)\n", slope);
    std::printf("  rays traced %llu in %.2f s: %.4g rays/s;  non-finite samples %llu\n",
                static_cast<unsigned long long>(rays), seconds, rays_per_second,
                static_cast<unsigned long long>(non_finite));
    std::printf("  wrote %s/{spp_NNNN.png,.pfm, noise_strip.png, rmse_vs_spp.csv,.png, "
                "summary.json}\n", o.common.out.string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Chapter 05: the noisy path tracer. One path per sample, one uniformly sampled "
               "direction per bounce; images at growing spp and their RMS error, estimated "
               "from two independent renders.",
               "ch05_path_tracer"};
  Options o;
  add_common_options(app, o.common, Chapter{"ch05_path_tracer", ""});
  add_scene_options(app, o.scene);
  add_image_options(app, o.image);
  app.add_option("--spp", o.spp, "Samples per pixel of each image (a list: 1,4,16)")
      ->delimiter(',')
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--depth", o.depth, "Bounces after the first hit (0: emitted light only)")
      ->check(CLI::Range(0, 1000));
  return run_chapter(app, argc, argv, [&] { return run(app, o); });
}
