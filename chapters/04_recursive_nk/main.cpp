// Chapter 04: the recursive N^k estimator, and why it cannot be the answer.
//
//   incidentRadiance(x, w):                      (common/render/recursive_estimator.hpp)
//     p = intersectScene(x, w);  L = p.emittedLight(-w)
//     if depth == k: return L                    // the stopping rule the lecture leaves out
//     for i = 1..N: wi uniform on the hemisphere; L += incidentRadiance(p, wi) f_r cos / (N pdf)
//     return L
//
//   for each N in --branching, for each k = 0..--max-depth:
//     image = render with incidentRadiance (N branches per hit, cut at depth k)
//     record its rays (closest-hit queries), its time and its mean radiance
//   limit = the mean radiance with N = 1 cut far deeper: what every cut at k is missing
//   at one ray budget per pixel: N = 1 with many camera samples against N > 1 with few
//   grid.png: N = 1 at --grid-spp for every k (the light each cut misses), above the
//   equal-cost renders (spp and RMS error): the two lessons apart, each at a fair cost
//
// Its three problems become numbers: the rays grow as N^k, the cut at depth k drops the light
// of longer paths, and branching is a poor way to spend rays against noise.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli.hpp"
#include "app/memory_limit.hpp"
#include "io/output.hpp"
#include "app/ray_limit.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "render/recursive_estimator.hpp"
#include "render/recursive_render.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "render/two_render_error.hpp"

#include "equal_cost.hpp"
#include "plan.hpp"
#include "plots.hpp"
#include "report.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch04_recursive_nk",
                        "Chapter 04: the recursive N^k estimator. At every hit N new directions, "
                        "each followed recursively to depth k: counts the rays (N^k), the light "
                        "lost by cutting at k, and compares branching with camera samples at "
                        "equal cost."};

// The light missing at depth k is measured with N = 1 (at most k + 1 rays a sample) and many
// samples, at every k and at a depth deep enough to stand for the limit: this one, or twice
// --max-depth if that is deeper. In the Cornell box no surface keeps more than 0.73 of the
// light it receives, so paths longer than 32 bounces carry under 0.73^33 ~ 3e-5 of it. All
// these renders share their random numbers (same seed and streams), and with N = 1 the path
// cut at k + 1 extends the path cut at k, so their differences are far less noisy than they.
constexpr int k_limit_depth = 32;
constexpr int k_light_spp = 64;
// grid.png's radiance is multiplied by this before the sRGB encoding (2 stops), so that the
// walls, which receive a few percent of the lamp's radiance, are not black.
constexpr double k_grid_exposure = 2.0;

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{128, 96};
  int spp = 1;                             // camera samples per pixel in the sweep
  std::vector<int> branching{1, 2, 4, 8};  // N, the directions sampled at every hit
  int max_depth = 4;                       // the largest k of the sweep
  double max_rays = 2e9;                   // refuse runs predicted to trace more rays
  int equal_cost_depth = 3;                // k of the equal-cost comparison
  int budget = 600;                        // rays per pixel of each equal-cost render
  int grid_spp = 1024;                     // samples per pixel of grid.png's top row (N = 1)
};

// 1. The explosion: every N, every k (rays.csv).
Table sweep(RecursiveRenderer& render_recursive, const Options& o) {
  Table rays = rays_table();
  const std::uint64_t pixels = static_cast<std::uint64_t>(o.image.width) * o.image.height;
  for (int n : o.branching)
    for (int k = 0; k <= o.max_depth; ++k) {
      const RenderResult r = render_recursive({n, k}, o.spp, 0);
      rays.add_row({n, k, r.rays, pixels * o.spp * max_rays_per_sample(n, k), r.seconds,
                    r.rays_per_second(), mean_radiance(r.image)});
    }
  return rays;
}

// 2. The missing light, measured closely: N = 1 with many samples at every k, and deep.
Table missing_light(RecursiveRenderer& render_recursive, const Options& o, const Plan& plan) {
  Table missing = missing_light_table();
  std::vector<double> mean_by_depth;
  for (int k = 0; k <= o.max_depth; ++k)
    mean_by_depth.push_back(mean_radiance(render_recursive({1, k}, k_light_spp, 0).image));
  const double limit = mean_radiance(render_recursive({1, plan.limit_depth}, k_light_spp, 0).image);
  for (int k = 0; k <= o.max_depth; ++k) {
    const double mean = mean_by_depth[static_cast<std::size_t>(k)];
    missing.add_row({k, mean, limit, limit > 0.0 ? 1.0 - mean / limit : 0.0});
  }
  return missing;
}

void run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  const Plan plan = make_plan(o, k_limit_depth, k_light_spp);
  check_plan(o, plan);
  // The grid keeps an image per depth and per N, three times over at most (the renders, their
  // blown-up copies, the sheet: images wider than 256 are not blown up, and narrower ones are
  // small), beside 4 more (measured: 175 bytes per pixel at --branching 1 --max-depth 1 with the
  // earlier grid of N x (depth + 1) images, counted 192).
  check_memory_limit(images_in_memory(static_cast<double>(o.image.width) * o.image.height,
                                      4.0 + 3.0 * (static_cast<double>(o.branching.size()) +
                                                   o.max_depth + 1),
                                      o.common.threads, "4 + 3 x (N values + depth + 1) images"),
                     "--width, --height, --branching, --max-depth", "lower them");
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);

  ProgressBar progress("ch04 sweep", static_cast<std::uint64_t>(plan.predicted_rays),
                       o.common.quiet);
  RecursiveRenderer render_recursive{scene, camera, o.common.seed, o.common.threads, &progress, {}};
  const Table rays = sweep(render_recursive, o);
  const Table missing = missing_light(render_recursive, o, plan);
  std::vector<Image> by_depth, at_equal_cost;  // grid.png's two rows
  for (int k = 0; k <= o.max_depth; ++k)
    by_depth.push_back(render_recursive({1, k}, o.grid_spp, 0).image);
  const Table equal = equal_cost(render_recursive, o, plan, at_equal_cost);
  progress.finish();
  const std::vector<double> error = equal.numbers("rms_error_at_budget");
  const auto best =
      static_cast<std::size_t>(std::min_element(error.begin(), error.end()) - error.begin());
  const std::string verdict = conclusion(o, equal, best);

  write_csv(o.common.dir / "rays.csv", rays);
  write_csv(o.common.dir / "missing_light.csv", missing);
  write_csv(o.common.dir / "equal_cost.csv", equal);
  write_plots(o.common.dir, o.branching, o.spp, k_light_spp,
              missing.at(0, "limit_mean_radiance").number(), plan.limit_depth, o.budget,
              o.equal_cost_depth, rays.numbers("mean_radiance"), error);
  write_grid(o.common.dir, std::move(by_depth), std::move(at_equal_cost), missing, equal,
             o.grid_spp, o.budget, k_grid_exposure, o.image.width);
  write_plot(o.common.dir,
             missing_light_plot(missing.numbers("missing_fraction"),
                                o.scene.scene == "furnace" ? o.scene.params.furnace_albedo : 0.0,
                                k_light_spp, plan.limit_depth));
  write_summary(k_chapter, app, o, plan, render_recursive, rays, missing, equal, best, verdict,
                k_light_spp);
  if (!o.common.quiet)
    print_tables(k_chapter, o, render_recursive.total, rays, missing, equal, verdict, k_light_spp);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image);
  add_number_option(app, "--spp", o.spp, "Camera samples per pixel in the sweep", 1, 1 << 16);
  add_list_option(app, "--branching", o.branching,
                  "Branching factors N, comma separated (each >= 1)", 1, 1 << 16);
  add_number_option(app, "--max-depth", o.max_depth,
                    "Largest depth k of the sweep (0 = emission only)", 0, 64);
  add_number_option(app, "--max-rays", o.max_rays,
                    "Refuse runs predicted to trace more rays than this (e.g. 2e9)", 1.0, 1e15);
  add_number_option(app, "--equal-cost-depth", o.equal_cost_depth,
                    "Depth k of the equal-cost comparison", 0, 64);
  add_number_option(app, "--budget", o.budget, "Rays per pixel of each equal-cost render", 1,
                    1 << 20);
  add_number_option(app, "--grid-spp", o.grid_spp,
                    "Samples per pixel of each panel of grid.png's top row (N = 1, every k)", 1,
                    1 << 16);
  return app.run(argc, argv, [&] { run(app, o); });
}
