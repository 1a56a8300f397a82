// Chapter 08: next-event estimation and MIS, and the shoot-out of every estimator.
//
//   for each sample:
//     shoot a ray into the scene; add the emitted light of its first hit
//     repeat until Russian roulette stops the path (or it has bounced --depth times):
//       pick a point y on a light, probability p_A(y) per unit area
//       trace a shadow ray to y; if it gets there add
//         weight * f_r * Le * cos(theta_x) * cos(theta_y) / (r^2 * p_A(y))     (NEE)
//       pick a new direction wi with pdf cos / pi, multiply the weight by f_r cos / pdf
//       (MIS: the light sample and the new direction's hit on a light are both added, each
//        weighted by w = p_s^2 / (p_light^2 + p_bsdf^2), and w_light + w_bsdf = 1)
//     set the sample colour to the sum
//   then, for every scene, every estimator, the same ray budgets: error against a reference
//
// Aiming at the light turns the noise of a small bright lamp (which a bouncing path finds by
// luck) into the noise of one shadow ray. For a large dim light the cosine already finds it,
// and MIS keeps whichever of the two strategies suits each direction.

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/cli.hpp"
#include "io/image_file.hpp"
#include "app/memory_limit.hpp"
#include "app/reference_cache.hpp"
#include "io/table.hpp"
#include "render/mis.hpp"
#include "render/next_event_estimation.hpp"
#include "render/relative_error.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

#include "estimators.hpp"
#include "light_choice.hpp"
#include "plan.hpp"
#include "plates.hpp"
#include "plots.hpp"
#include "report.hpp"
#include "shootout.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch08_next_event_estimation",
                        "Chapter 08: next-event estimation (a shadow ray to a point on a light "
                        "at every bounce) and multiple importance sampling, then an equal-ray "
                        "shoot-out of every estimator of chapters 05-08 on the furnace, the "
                        "Cornell box at light scales 0.1, 1 and 3, and the sphere Cornell box."};

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{160, 120};
  int spp = 16;                                 // samples per pixel of nee.pfm and mis.pfm
  int depth = -1;                               // bounces after the first hit; -1: roulette only
  int reference_spp = 1024;                     // samples per pixel of every reference
  std::filesystem::path reference_dir;          // default: the user's cache folder
  std::vector<int> budgets{64, 128, 256, 512};  // rays per pixel, per estimator and scene
  int plates_spp = 16;                          // samples per pixel of Veach's plates (plates.hpp)
};

// nee.pfm/.png and mis.pfm/.png of the chosen scene at --spp, and their error (images.csv).
Table render_chosen_scene(const Options& o, const Reference& reference, RenderTotals& total) {
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  Table table({{"image", Column::text},
               {"spp", Column::integer},
               {"rays", Column::integer},
               {"rel_mse", Column::real, 6}});
  for (const auto& [stem, kind] :
       {std::pair{"nee", EstimatorKind::nee}, std::pair{"mis", EstimatorKind::mis_power}}) {
    const RenderResult r = render(camera, {o.spp, 0, o.common.seed, o.common.threads, nullptr},
                                  make_estimator(kind, scene, o.depth));
    total.add(r);
    write_png(o.common.dir / (std::string(stem) + ".png"), r.image);
    write_pfm(o.common.dir / (std::string(stem) + ".pfm"), r.image);
    table.add_row({stem, o.spp, r.rays, relative_mse(r.image, reference.image)});
  }
  return table;
}

void run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  // The shoot-out's furnace ends paths by roulette only: at albedo 1 they never end.
  check_furnace_albedo(o.scene.params.furnace_albedo);
  check_ray_limit(predicted_work(o), k_max_rays,
                  "--spp, --reference-spp, --plates-spp, --width, --height, --albedo",
                  o.common.threads, "lower one of them");
  // Every scene's estimators and references, their snapshots and the contact sheet (measured:
  // 3.4 KB per pixel at 512x256 whatever --ray-budgets with five scenes; counted 170 images,
  // 4 KB; smallpt's row keeps 7 more: 180).
  check_memory_limit(images_in_memory(static_cast<double>(o.image.width) * o.image.height, 180.0,
                                      o.common.threads, "about 180 images of --width x --height"),
                     "--width, --height", "lower them");
  const std::filesystem::path reference_dir = reference_folder(o.reference_dir);
  check_reference_folder(reference_dir, o.common.out);

  const Reference reference =
      load_or_render_reference(reference_dir,
                               reference_spec(o, o.scene.scene, o.scene.params.light_scale));
  RenderTotals total;
  const Table images = render_chosen_scene(o, reference, total);

  Shootout shootout;
  const std::vector<ShootoutScene> scenes = shootout_scenes();
  for (const ShootoutScene& s : scenes)
    shoot_out_scene(s,
                    load_or_render_reference(reference_dir,
                                             reference_spec(o, s.scene, s.light_scale)),
                    o, shootout);
  total.seconds += shootout.total.seconds;
  total.rays += shootout.total.rays;
  total.non_finite_samples += shootout.total.non_finite_samples;

  write_csv(o.common.dir / "images.csv", images);
  write_csv(o.common.dir / "efficiency.csv", shootout.table);
  for (const ShootoutScene& s : scenes) write_relmse_plot(o.common.dir, s);
  write_contact_sheet(o.common.dir, scenes, shootout, o.budgets.back());

  const PlatesStudy plates = run_plates_study(o.image.width, o.image.height, o.plates_spp,
                                              o.common.seed, o.common.threads);
  total.seconds += plates.total.seconds;
  total.rays += plates.total.rays;
  total.non_finite_samples += plates.total.non_finite_samples;
  write_plates(o.common.dir, plates, o.plates_spp);
  const LightChoiceStudy light_choice = run_light_choice_study(o.common.seed);
  write_light_choice(o.common.dir, light_choice);
  write_summary(k_chapter, app, o, images, shootout, reference.info, total, plates.table,
                light_choice.table);
  if (!o.common.quiet) print_report(k_chapter, o, images, shootout.table, total);
  if (!o.common.quiet) fmt::print("{}", plates_console(plates));
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image, scene_names());  // veach-plates too: glossy lobes
  add_number_option(app, "--light-scale", o.scene.params.light_scale,
                    "cornell: the lamp's sides times this, its radiance over its square (the "
                    "same power): 0.1 tiny and bright, 3 large and dim",
                    0.01, k_max_light_scale);
  add_number_option(app, "--spp", o.spp, "Samples per pixel of nee.pfm and mis.pfm", 1, 1 << 16);
  show_default_as(
      add_number_option(
          app, "--depth", o.depth,
          "Cut every path after this many bounces (default: no cut, Russian roulette only)", 0,
          1000),
      "none");
  add_number_option(app, "--reference-spp", o.reference_spp,
                    "Samples per pixel of each reference image (cached under --reference-dir)", 2,
                    1 << 20);
  add_reference_dir_option(app, o.reference_dir);
  add_list_option(app, "--ray-budgets", o.budgets,
                  "Ray budgets of the shoot-out, in rays traced per pixel by each estimator on "
                  "each scene (a list: 64,128,256,512)",
                  1, 1000000);
  add_number_option(app, "--plates-spp", o.plates_spp,
                    "Samples per pixel of each strategy on Veach's plates (plates.png, "
                    "plates.csv; 3 rays a sample, the reference 16 times as many)",
                    1, 1 << 12);
  return app.run(argc, argv, [&] { run(app, o); });
}
