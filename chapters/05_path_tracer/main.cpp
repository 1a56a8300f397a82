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
// B at the same spp: E[(A - B)^2] / 2 = Var[A] = the mean squared error of A. That estimate
// cannot see bias: the light the depth cut drops is missing from A and B alike. So each image
// is also compared with a converged reference without a depth cut (chapter 08's estimator,
// cached under out/reference/): E[(A - R)^2] = Var[A] + bias^2 + Var[R], which stops falling
// once the noise is below the bias.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "integration/statistics.hpp"
#include "io/cli.hpp"
#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "io/ray_limit.hpp"
#include "io/reference_cache.hpp"
#include "io/render_summary.hpp"
#include "io/summary.hpp"
#include "io/table.hpp"
#include "render/path_tracer.hpp"
#include "render/relative_error.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"
#include "render/two_render_error.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch05_path_tracer",
                        "Chapter 05: the noisy path tracer. One path per sample, one uniformly "
                        "sampled direction per bounce; images at growing spp and their RMS error, "
                        "estimated from two independent renders."};

// The most rays one run may trace: about 1.4 hours at 2e7 rays per second.
constexpr double k_max_rays = 1e11;
// A generous mean of rays per sample of the reference's estimator (MIS: 2 per vertex).
constexpr double k_reference_rays_per_sample = 32.0;

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{256, 192};
  std::vector<int> spp{1, 4, 16, 64, 256};  // samples per pixel of each image
  int depth = 10;                           // bounces after the camera ray's hit
  int reference_spp = 1024;                 // 0: no reference, no error against it
  std::filesystem::path reference_dir;      // default: --out's parent / reference
};

// The reference: the same scene and size, no depth cut, its own sample streams.
ReferenceSpec reference_spec(const Options& o) {
  ReferenceSpec spec;
  spec.scene = o.scene;
  spec.width = o.image.width;
  spec.height = o.image.height;
  spec.spp = o.reference_spp;
  spec.max_depth = -1;
  spec.seed = o.common.seed;
  spec.threads = o.common.threads;
  spec.quiet = o.common.quiet;
  return spec;
}

// The most rays the run can trace: two renders per spp, at most depth + 1 rays per sample,
// and the reference if it is not cached.
RayWork predicted_work(const Options& o) {
  double samples = 0.0;
  for (int spp : o.spp) samples += 2.0 * spp;
  const double reference = o.reference_spp > 0 ? reference_predicted_rays(
                                                      reference_spec(o), k_reference_rays_per_sample)
                                                : 0.0;
  return {samples * o.image.width * o.image.height * (o.depth + 1.0) + reference,
          "2 renders x sum of spp x pixels x (depth + 1) + reference spp x pixels x 32"};
}

// rmse_vs_spp.csv: one row per spp, its two-render RMS error, its RMS error against the
// reference (empty without one) and the cost of both renders.
Table rmse_table() {
  return Table({{"spp", Column::integer},
                {"rmse", Column::real, 9},  // sqrt(mean over pixels and channels of (A - B)^2 / 2)
                {"rmse_vs_reference", Column::real, 9},  // sqrt(mean of (A - R)^2)
                {"seconds", Column::real, 6},
                {"rays", Column::integer},
                {"rays_per_second", Column::real, 6}});
}

// Two independent renders at `spp`: A takes samples [0, spp), B takes [spp, 2 spp). The A
// images of growing spp share their first samples, so they show one image converging.
std::pair<RenderResult, RenderResult> render_pair(const Scene& scene, const Camera& camera,
                                                  int spp, const Options& o) {
  ProgressBar progress(fmt::format("ch05 {:4} spp", spp), 2ull * o.image.height, o.common.quiet);
  const auto path_radiance = [&](const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_path_radiance(scene, ray, o.depth, rng, count);
  };
  const auto first_sample = static_cast<std::uint64_t>(spp);
  RenderResult a = render(camera, {spp, 0, o.common.seed, o.common.threads, &progress}, path_radiance);
  RenderResult b =
      render(camera, {spp, first_sample, o.common.seed, o.common.threads, &progress}, path_radiance);
  progress.finish();
  return {std::move(a), std::move(b)};
}

// The slope of log RMS error against log spp; NaN with fewer than two points or a zero error.
double fitted_slope(const Table& errors) {
  const std::vector<double> spp = errors.numbers("spp"), rmse = errors.numbers("rmse");
  const bool can_fit = spp.size() >= 2 && std::all_of(rmse.begin(), rmse.end(),
                                                       [](double e) { return e > 0.0; });
  return can_fit ? fit_log_log(spp, rmse).slope : std::nan("");
}

// The bias the depth cut leaves, estimated at the largest spp: the error against the reference
// less the noise of A (two-render) and of R, sqrt(max(0, E_ref^2 - E_AB^2 - E_R^2)). NaN
// without a reference.
double depth_cut_bias_rms(const Table& errors, const Reference* reference) {
  if (reference == nullptr) return std::nan("");
  const std::size_t last = errors.size() - 1;
  const double against_reference = errors.at(last, "rmse_vs_reference").number();
  const double noise = errors.at(last, "rmse").number();
  const double reference_noise = reference->info.value("standard_error_rms", 0.0);
  return std::sqrt(std::max(0.0, against_reference * against_reference - noise * noise -
                                     reference_noise * reference_noise));
}

void write_rmse_plot(const Options& o, const Table& errors, double slope, bool has_reference) {
  // The reference line of slope -1/2 passes through the first point.
  std::string settings =
      fmt::format("rmse1 = {:.9g}\nspp1 = {}\nset key top right\n", errors.at(0, "rmse").number(),
                  o.spp.front()) +
      (std::isfinite(slope)
           ? fmt::format("set label 1 'fitted slope {:.3f} (theory -0.5)' at graph 0.05, graph 0.1\n",
                         slope)
           : std::string());
  if (o.spp.size() > 1)  // the x axis ends where the data end
    settings += fmt::format("set xrange [{}:{}]\n", o.spp.front(), o.spp.back());
  Plot plot{"rmse_vs_spp", "RMS error against samples per pixel",
            "samples per pixel", "RMS error", true, true, settings,
            "plot 'rmse_vs_spp.csv' using \"spp\":\"rmse\" with linespoints pt 7 lw 2 title "
            "'two-render estimate (noise only)', rmse1 * (x / spp1)**-0.5 with lines dt 2 "
            "lc 'black' title 'slope -1/2'"};
  plot.x_values = errors.numbers("spp");  // one spp, or zero error (no light): still a plot
  plot.y_values = errors.numbers("rmse");
  if (has_reference) {
    plot.plot += ", 'rmse_vs_spp.csv' using \"spp\":\"rmse_vs_reference\" with linespoints "
                     "pt 5 lw 2 title 'against the reference (noise and bias)'";
    const std::vector<double> against = errors.numbers("rmse_vs_reference");
    plot.y_values.insert(plot.y_values.end(), against.begin(), against.end());
  }
  write_plot(o.common.dir, plot);
}

void write_summary(const CLI::App& app, const Options& o, const Table& errors, double slope,
                   const RenderTotals& total, const Image& last, const Reference* reference) {
  Json summary = start_summary(k_chapter, o.common);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  summary["depth"] = o.depth;
  add_render_totals(summary, total);
  summary["rmse_slope"] = std::isfinite(slope) ? Json(slope) : Json(nullptr);  // < 2 spp
  summary["rmse_slope_theory"] = -0.5;
  summary["mean_radiance"] = mean_radiance(last);
  summary["rmse_vs_spp"] = errors.json();
  const double bias = depth_cut_bias_rms(errors, reference);
  summary["depth_cut_bias_rms"] = std::isfinite(bias) ? Json(bias) : Json(nullptr);
  summary["mean_radiance_reference"] =
      reference ? Json(mean_radiance(reference->image)) : Json(nullptr);
  summary["reference"] = reference ? Json(reference->info) : Json(nullptr);
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(k_chapter, o.common);
  add_render_timings(timings, total);
  write_timings(o.common.dir, timings, app);
}

void print_table(const Options& o, const Table& errors, double slope, const RenderTotals& total,
                 const Image& last, const Reference* reference) {
  fmt::print("{}  scene {}  {}x{}  depth {}  {} threads\n", k_chapter.name, o.scene.scene,
             o.image.width, o.image.height, o.depth, o.common.threads);
  fmt::print("{}", errors.console({"spp", "rmse", "rmse_vs_reference", "seconds",
                                   "rays_per_second"}));
  if (std::isfinite(slope))
    fmt::print("  fitted slope of log RMS error against log spp: {:.3f} (theory -0.5)\n", slope);
  if (reference)
    fmt::print("  rmse = two-render estimate (noise only); rmse_vs_reference also holds the "
               "depth cut's bias, about {:.3g} RMS\n  mean radiance {:.5g}, reference {:.5g} "
               "(without a depth cut)\n", depth_cut_bias_rms(errors, reference), mean_radiance(last),
               mean_radiance(reference->image));
  fmt::print("  rays traced {} in {:.2f} s: {:.4g} rays/s;  non-finite samples {}\n", total.rays,
             total.seconds, total.rays_per_second(), total.non_finite_samples);
  fmt::print("  wrote {}/{{spp_NNNN.png,.pfm, noise_strip.png, rmse_vs_spp.csv,.png, "
             "summary.json, timings.json}}\n", o.common.out.string());
}

void run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  check_ray_limit(predicted_work(o), k_max_rays, "--spp, --depth, --width, --height",
                  o.common.threads, "lower one of them");
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  std::optional<Reference> reference;
  if (o.reference_spp > 0)
    reference = load_or_render_reference(
        o.reference_dir.empty() ? o.common.out.parent_path() / "reference" : o.reference_dir,
        reference_spec(o));

  Table errors = rmse_table();
  RenderTotals total;
  std::vector<Image> images;
  std::vector<std::string> labels;
  for (int spp : o.spp) {
    const auto [a, b] = render_pair(scene, camera, spp, o);
    RenderTotals pair = totals_of(a);
    pair.add(b);
    const Cell against_reference =
        reference ? Cell(rms_error(a.image, reference->image)) : Cell();  // empty without one
    errors.add_row({spp, two_render_rms_error(a.image, b.image), against_reference, pair.seconds,
                    pair.rays, pair.rays_per_second()});
    total.add(a);
    total.add(b);
    const std::string stem = fmt::format("spp_{:04}", spp);
    write_png(o.common.dir / (stem + ".png"), a.image);
    write_pfm(o.common.dir / (stem + ".pfm"), a.image);
    images.push_back(a.image);
    labels.push_back(fmt::format("{} spp", spp));
  }
  const double slope = fitted_slope(errors);

  // Below the raw details, their 8x8 means: at low spp the light sits in a few bright pixels.
  write_png(o.common.dir / "noise_strip.png",
            centre_detail_strip(images, labels, "at growing spp", 8));
  write_csv(o.common.dir / "rmse_vs_spp.csv", errors);
  const Reference* r = reference ? &*reference : nullptr;
  write_rmse_plot(o, errors, slope, r != nullptr);
  write_summary(app, o, errors, slope, total, images.back(), r);
  if (!o.common.quiet) print_table(o, errors, slope, total, images.back(), r);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image);
  add_list_option(app, "--spp", o.spp, "Samples per pixel of each image (a list: 1,4,16)", 1,
                  1 << 16);
  add_number_option(app, "--depth", o.depth, "Bounces after the first hit (0: emitted light only)",
                    0, 1000);
  add_number_option(app, "--reference-spp", o.reference_spp,
                    "Samples per pixel of the reference image, without a depth cut (cached under "
                    "--reference-dir; 0: no reference)", 0, 1 << 20);
  app.add_option("--reference-dir", o.reference_dir,
                 "Folder of the cached references (default: the reference folder beside --out)");
  return app.run(argc, argv, [&] { run(app, o); });
}
