// Chapter 06: Russian roulette, a stopping rule without bias.
//
//   for each sample:
//     shoot a ray into the scene
//     repeat until the path leaves the scene or is stopped:
//       find the closest intersection
//       add its emitted light, times the path weight
//       once the path has --min-depth bounces:
//         go on with probability q, else stop       (q fixed, or the path weight's largest part)
//         divide the path weight by q               (the survivors carry what the stopped lost)
//       pick one new direction uniformly on the hemisphere
//       multiply the weight by f_r cos(theta) / pdf
//     set the sample colour to the sum
//
// There is no depth cut, so the estimate is unbiased for the whole series (common/render/
// russian_roulette.hpp). The furnace, where E[L] = Le / (1 - a), makes every claim a number:
//   bias:         the depth cut at k against roulette after k bounces, k = 0..--depth
//   efficiency:   for each q of --q: variance, rays per path, seconds, 1 / (variance x time)
//   path length:  the rays of each path at --fixed-q against the geometric law
//   splitting:    the first hit split into n paths of 1/n its weight, for each n of --split
//                 and q of --split-q: variance, rays per path, 1 / (variance x rays)
// (furnace_studies.hpp, splitting_study.hpp), and the chosen --scene is rendered both ways at --spp.

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "io/table.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"

#include "furnace_studies.hpp"
#include "plan.hpp"
#include "plots.hpp"
#include "renders.hpp"
#include "report.hpp"
#include "splitting_study.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch06_russian_roulette",
                        "Chapter 06: Russian roulette. Chapter 05's path tracer without a depth "
                        "cut: after --min-depth bounces a path goes on with probability q and its "
                        "weight is divided by q. In the furnace: the depth cut's bias against "
                        "roulette's, the variance, rays and time of each q, and the path lengths; "
                        "then the scene rendered both ways."};

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{256, 192};
  int spp = 64;    // samples per pixel of both images
  int depth = 10;  // the depth cut of depth_cut.png, and the largest k of bias.csv
  // --min-depth, --policy, --fixed-q and --floor:
  Roulette roulette{3, RoulettePolicy::throughput, 0.7, 0.05};
  std::vector<double> q{0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95};  // the efficiency sweep
  int paths = 200000;  // furnace paths per row of every study (/ n for splitting.csv)
  std::vector<double> split_q{0.6, 0.8};     // the splitting study's fixed q
  std::vector<int> split_n{1, 2, 4, 8, 16};  // the splitting study's n
};

struct Results {
  Table bias, efficiency, lengths, renders, splitting;
  PathStats fixed_paths;
  RenderTotals total;
};

void run(const CLI::App& app, const Options& o) {
  check_request(o);
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  const SceneParams& p = o.scene.params;
  const Furnace furnace{make_furnace(p.furnace_albedo, p.furnace_emission),
                        p.furnace_albedo,
                        p.furnace_emission,
                        o.paths,
                        o.common.seed,
                        o.common.threads,
                        o.depth,
                        o.roulette,
                        o.q};

  Results r{bias_study(furnace),
            efficiency_study(furnace),
            Table({}),
            renders_table(),
            splitting_study(furnace, o.split_q, o.split_n),
            {},
            {}};
  r.lengths = path_length_study(furnace, r.fixed_paths);
  const RenderResult cut =
      render_image(camera, o, "depth_cut", [&](const Ray& ray, Rng& rng, RayCount& count) {
        return estimate_path_radiance(scene, ray, o.depth, rng, count);
      });
  const RenderResult roulette =
      render_image(camera, o, "roulette", [&](const Ray& ray, Rng& rng, RayCount& count) {
        return estimate_path_radiance_roulette(scene, ray, o.roulette, rng, count);
      });
  add_render_row(r.renders, "depth_cut", cut, o);
  add_render_row(r.renders, "roulette", roulette, o);
  r.total.add(cut);
  r.total.add(roulette);

  write_csv(o.common.dir / "bias.csv", r.bias);
  write_csv(o.common.dir / "efficiency.csv", r.efficiency);
  write_csv(o.common.dir / "path_length.csv", r.lengths);
  write_csv(o.common.dir / "renders.csv", r.renders);
  write_csv(o.common.dir / "splitting.csv", r.splitting);
  write_plots(o.common.dir, o, r.efficiency, r.bias);
  write_splitting_plot(o.common.dir, p.furnace_albedo, p.furnace_emission, o.roulette.min_depth,
                       o.split_q, r.splitting);
  write_summary(k_chapter, app, o, r);
  if (!o.common.quiet) print_tables(k_chapter, o, r);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image, scene_names());  // veach-plates too: glossy lobes
  add_number_option(app, "--spp", o.spp, "Samples per pixel of both images", 1, 1 << 16);
  add_number_option(app, "--depth", o.depth,
                    "Bounces of the depth cut (depth_cut.png; bias.csv's largest k)", 0, 1000);
  add_number_option(app, "--min-depth", o.roulette.min_depth, "Bounces before roulette starts", 0,
                    1000);
  add_choice_option(
      app, "--policy", {"fixed", "throughput"}, "throughput",
      [&](const std::string& name) {
        o.roulette.policy = name == "fixed" ? RoulettePolicy::fixed : RoulettePolicy::throughput;
      },
      "Roulette of the image and bias.csv: fixed (--fixed-q) or throughput (q = the path "
      "weight's largest part, at least --floor)");
  add_number_option(app, "--fixed-q", o.roulette.q, "q of --policy fixed and of path_length.csv",
                    k_lowest_q, k_highest_q);
  add_number_option(app, "--floor", o.roulette.floor, "Least q of the throughput policy",
                    k_lowest_q, k_highest_q);
  add_list_option(app, "--q", o.q, "The fixed q of the efficiency sweep (a list)", k_lowest_q,
                  k_highest_q);
  add_number_option(app, "--paths", o.paths, "Furnace paths per row of every study", 100,
                    100000000);
  add_list_option(app, "--split-q", o.split_q, "The fixed q of the splitting study (a list)",
                  k_lowest_q, k_highest_q);
  add_list_option(app, "--split", o.split_n, "The n of the splitting study (a list)", 1, 64);
  return app.run(argc, argv, [&] { run(app, o); });
}
