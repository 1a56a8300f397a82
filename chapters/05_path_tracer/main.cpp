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
// cached in the user's cache folder, --reference-dir): E[(A - R)^2] = Var[A] + bias^2 + Var[R], which stops falling
// once the noise is below the bias. To show it, the same pairs are rendered again at a few
// shallow depths (--bias-depths, default 0, 1, 2), whose bias is large: rmse_vs_spp.png draws
// their two-render error falling on while their error against the reference levels off.
//
// The loop above is estimate_path_radiance (render/path_tracer.hpp). By default the chapter
// runs it four paths at a time (engine/path_tracer_lanes.hpp, --engine lanes): the same image,
// bit for bit, 1.2x to 1.7x as fast (1.7x on the spheres of cornell-spheres, 1.2x on the
// quads of cornell); --engine loop runs it one path at a time.
//
// --sampler jittered or sobol draws each pixel's samples from padded 2D point sets instead of
// independent streams (render/sampled_render.hpp, chapter 09): the pixel positions, and each
// bounce's direction, stratified across the pixel's spp samples; the four lanes take the same
// points. Each of A and B is a point set of its own, so the A images of growing spp no longer
// share their first samples.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "integration/statistics.hpp"
#include "app/cli.hpp"
#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "app/reference_cache.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "render/path_tracer.hpp"
#include "engine/path_tracer_lanes.hpp"
#include "render/relative_error.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/sampled_render.hpp"
#include "render/scene.hpp"
#include "render/two_render_error.hpp"
#include "options.hpp"
#include "plan.hpp"
#include "report.hpp"

using namespace mcrt;
using namespace mcrt::ch05;

namespace {

const Chapter k_chapter{"ch05_path_tracer",
                        "Chapter 05: the noisy path tracer. One path per sample, one uniformly "
                        "sampled direction per bounce; images at growing spp and their RMS error, "
                        "estimated from two independent renders and measured against a "
                        "converged reference (which also shows the depth cut's bias)."};

// Two independent renders at `spp`: A takes samples [0, spp), B takes [spp, 2 spp). The A
// images of growing spp share their first samples, so they show one image converging.
std::pair<RenderResult, RenderResult> render_pair(const Scene& scene, const Camera& camera, int spp,
                                                  int depth, const Options& o) {
  ProgressBar progress(fmt::format("ch05 {:4} spp depth {}", spp, depth), 2ull * o.image.height,
                       o.common.quiet);
  const auto render_paths = [&](std::uint64_t first_sample) {
    const RenderSettings settings{spp, first_sample, o.common.seed, o.common.threads, &progress};
    if (o.lanes) return render_path_tracer_lanes(scene, camera, settings, depth, o.sampler);
    return render_sampled(camera, settings, o.sampler,
                          [&](const Ray& ray, auto& rng, RayCount& count) {
                            return estimate_path_radiance(scene, ray, depth, rng, count);
                          });
  };
  RenderResult a = render_paths(0);
  RenderResult b = render_paths(static_cast<std::uint64_t>(spp));
  progress.finish();
  return {std::move(a), std::move(b)};
}

void run(const CLI::App& app, const Options& o) {
  refuse_impossible_work(o);
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  std::optional<Reference> reference;
  if (o.reference_spp > 0)
    reference = load_or_render_reference(reference_dir(o), reference_spec(o));

  Table errors = rmse_table();
  RenderTotals total;
  std::vector<Image> images;
  std::vector<std::string> labels;
  for (int spp : o.spp) {
    const auto [a, b] = render_pair(scene, camera, spp, o.depth, o);
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

  // The bias study: only against a reference is there a bias to see.
  Table bias = depth_bias_table();
  if (reference)
    for (int depth : o.bias_depths)
      for (int spp : o.spp) {
        const auto [a, b] = render_pair(scene, camera, spp, depth, o);
        bias.add_row({depth, spp, two_render_rms_error(a.image, b.image),
                      rms_error(a.image, reference->image), a.rays + b.rays});
        total.add(a);
        total.add(b);
      }

  // smallpt's mirror and glass: a path meeting a delta follows its one direction (sampled by
  // the material, never uniformly: a uniform direction would never be the mirror's).
  std::uint64_t smallpt_rays = 0;
  if (o.smallpt_spp > 0) {
    const Scene smallpt = make_scene("smallpt", o.scene.params);
    ProgressBar progress("ch05 smallpt", o.image.height, o.common.quiet);
    const RenderResult s =
        render_path_tracer_lanes(smallpt, Camera(smallpt.camera, o.image.width, o.image.height),
                                 {o.smallpt_spp, 0, o.common.seed, o.common.threads, &progress},
                                 o.depth);
    progress.finish();
    write_png(o.common.dir / "smallpt.png", s.image);
    total.add(s);
    smallpt_rays = s.rays;
  }

  // Below the raw details, their 8x8 means: at low spp the light sits in a few bright pixels.
  write_png(o.common.dir / "noise_strip.png",
            centre_detail_strip(images, labels, "at growing spp", 8));
  write_csv(o.common.dir / "rmse_vs_spp.csv", errors);
  if (reference) write_csv(o.common.dir / "depth_bias.csv", bias);
  const Reference* r = reference ? &*reference : nullptr;
  write_rmse_plot(o, errors, slope, r != nullptr ? &bias : nullptr);
  write_summary(k_chapter, app, o, errors, slope, total, images.back(), r, bias, smallpt_rays);
  if (!o.common.quiet) print_table(k_chapter, o, errors, slope, total, images.back(), r);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_options(app, o);
  return app.run(argc, argv, [&] { run(app, o); });
}
