// Chapter 07: importance sampling, less noise from the same rays.
//
//   for each pdf p in {uniform, cosine, cos^2, cos^4, cos^8, grazing}:
//     for each sample:
//       shoot a ray into the scene
//       repeat until the path leaves the scene or has bounced --depth times:
//         find the closest intersection
//         add its emitted light, times the path weight
//         pick one new direction wi with probability density p(wi)
//         multiply the weight by f_r cos(theta) / p(wi)
//       set the sample colour to the sum
//     measure the variance of one sample, per pixel
//
// Chapter 05 with one change: the direction's pdf. Every pdf gives the same expected image;
// the one shaped like the integrand (the cosine) gives the least noise, and in the furnace
// none at all, since every bounce's weight f_r cos / p = (a/pi) cos / (cos/pi) is exactly a.
// A pdf that ignores the cosine (uniform), or fights it (grazing), or is narrower than it
// (cos^m, m >= 3: the variance is infinite) costs noise. The variance of one sample is
// measured without a reference from two independent renders A and B at the same spp:
// spp E[(A - B)^2] / 2 = spp Var[A] = Var[one sample].

#include <algorithm>
#include <cstdint>
#include <vector>

#include "app/cli.hpp"
#include "app/memory_limit.hpp"
#include "io/output.hpp"
#include "app/ray_limit.hpp"
#include "io/table.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

#include "equal_time.hpp"
#include "pdf_study.hpp"
#include "plots.hpp"
#include "report.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch07_importance_sampling",
                        "Chapter 07: importance sampling. Chapter 05's path tracer with the "
                        "bounce direction drawn from p ~ cos^m(theta) (m = 0 uniform, 1 cosine) "
                        "or a bad pdf favouring grazing directions: the per-pixel variance of "
                        "each, in the furnace and in a scene, and uniform against cosine at "
                        "equal samples and at equal time."};

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{192, 144};
  int spp = 16;                            // samples per pixel of every image of the study
  int depth = 10;                          // bounces after the camera ray's hit
  std::vector<int> powers{0, 1, 2, 4, 8};  // the m of p ~ cos^m; 0 and 1 are always in
  int reference_spp = 128;                 // the many-sample cosine image the errors are against
};

// The pdfs of the study: cos^m for every --powers m (0 and 1 added), then the grazing pdf.
std::vector<HemispherePdf> study_pdfs(std::vector<int> powers) {
  powers.insert(powers.end(), {0, 1});
  std::sort(powers.begin(), powers.end());
  powers.erase(std::unique(powers.begin(), powers.end()), powers.end());
  std::vector<HemispherePdf> pdfs;
  for (int m : powers) pdfs.push_back(cosine_power_pdf(m));
  pdfs.push_back({HemispherePdf::grazing, 0});
  return pdfs;
}

// Per pdf two renders of the scene and two of the furnace at spp; the equal-time cosine image
// (at most 2 spp: equal_time_spp), and the reference. At most depth + 1 rays per sample.
RayWork predicted_work(const Options& o) {
  const double pdfs = static_cast<double>(study_pdfs(o.powers).size());
  const double pixels = static_cast<double>(o.image.width) * o.image.height;
  const double samples = pdfs * 2.0 * o.spp * (pixels + k_furnace_side * k_furnace_side) +
                         (2.0 * o.spp + o.reference_spp) * pixels;
  return {samples * (o.depth + 1.0),
          "pdfs x 2 renders x spp x (pixels + furnace pixels) + (2 spp + reference spp) x pixels, "
          "x (depth + 1)"};
}

// The estimator of every render: the importance-sampled path tracer as the pixel loop's
// estimator, spp samples per pixel from sample number first_sample on.
struct RenderWithPdf {
  const Options& o;
  RenderResult operator()(const Scene& scene, const Camera& camera, const HemispherePdf& pdf,
                          int spp, std::uint64_t first_sample) const {
    return render(camera, {spp, first_sample, o.common.seed, o.common.threads, nullptr},
                  [&](const Ray& ray, Rng& rng, RayCount& count) {
                    return estimate_importance_path_radiance(scene, ray, o.depth, pdf, rng, count);
                  });
  }
};

void run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  // The furnace study's closed forms (mean and variance) diverge at albedo 1.
  check_furnace_albedo(o.scene.params.furnace_albedo);
  check_ray_limit(predicted_work(o), k_max_rays,
                  "--spp, --reference-spp, --depth, --width, --height", o.common.threads,
                  "lower one of them");
  // Per pdf its renders, beside the equal-time and reference images (measured: 245 bytes per
  // pixel with 2 pdfs, 397 with 5; counted 8 + 3 per pdf: 336 and 552).
  check_memory_limit(images_in_memory(static_cast<double>(o.image.width) * o.image.height,
                                      8.0 + 3.0 * static_cast<double>(study_pdfs(o.powers).size()),
                                      o.common.threads, "8 + 3 x pdfs images"),
                     "--width, --height, --powers", "lower them");
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  const std::vector<HemispherePdf> pdfs = study_pdfs(o.powers);

  const RenderWithPdf render_with{o};
  const Study study = run_study(render_with, scene, camera, pdfs, o);
  const EqualTime equal = compare_at_equal_time(render_with, study, scene, camera, o);
  RenderTotals total = study.total;
  total.add(equal.cosine_equal_time);
  total.add(equal.reference);

  write_images(o.common.dir, pdfs, study.images, equal.cosine_equal_time.image,
               equal.reference.image, o.spp);
  write_csv(o.common.dir / "variance_vs_m.csv", study.variances);
  write_csv(o.common.dir / "equal_time.csv", equal.table);
  write_variance_plot(o.common.dir, o.scene.scene, o.spp, study.variances,
                      o.scene.params.furnace_albedo, o.scene.params.furnace_emission, o.depth);
  write_summary(k_chapter, app, o, study.variances, equal.table, total);
  if (!o.common.quiet) print_report(k_chapter, o, study.variances, equal.table, total);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image, scene_names());  // veach-plates too: glossy lobes
  add_number_option(app, "--spp", o.spp, "Samples per pixel of every image of the study", 1,
                    1 << 16);
  add_number_option(app, "--depth", o.depth, "Bounces after the first hit (0: emitted light only)",
                    0, 1000);
  add_list_option(app, "--powers", o.powers,
                  "The powers m of p ~ cos^m(theta) to compare (a list: 0,1,2,4,8; 0 uniform "
                  "and 1 cosine are always in)",
                  0, 64);
  add_number_option(app, "--reference-spp", o.reference_spp,
                    "Samples per pixel of the cosine reference image (not used in the furnace)", 1,
                    1 << 16);
  return app.run(argc, argv, [&] { run(app, o); });
}
