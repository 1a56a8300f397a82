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
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "io/cli.hpp"
#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/output.hpp"
#include "io/ray_limit.hpp"
#include "io/render_summary.hpp"
#include "io/summary.hpp"
#include "io/table.hpp"
#include "plots.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"
#include "render/two_render_error.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch07_importance_sampling",
                        "Chapter 07: importance sampling. Chapter 05's path tracer with the "
                        "bounce direction drawn from p ~ cos^m(theta) (m = 0 uniform, 1 cosine) "
                        "or a bad pdf favouring grazing directions: the per-pixel variance of "
                        "each, in the furnace and in a scene, and uniform against cosine at "
                        "equal samples and at equal time."};

constexpr double k_max_rays = 1e11;    // about 1.4 hours at 2e7 rays per second
constexpr int k_furnace_side = 32;     // the furnace study's image: 32 x 32 pixels
// The reference's samples start here: far from every other render's [0, 2 spp), so independent.
constexpr std::uint64_t k_reference_first_sample = 1u << 20;

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{192, 144};
  int spp = 16;                          // samples per pixel of every image of the study
  int depth = 10;                        // bounces after the camera ray's hit
  std::vector<int> powers{0, 1, 2, 4, 8};  // the m of p ~ cos^m; 0 and 1 are always in
  int reference_spp = 128;               // the many-sample cosine image the errors are against
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

// variance_vs_m.csv: one row per pdf. Variances are of ONE sample, per pixel and channel.
Table variance_table() {
  return Table({{"pdf", Column::text},
                {"m", Column::integer},                       // empty for the grazing pdf
                {"furnace_variance", Column::real, 9},        // measured, spp (A - B)^2 / 2
                {"furnace_variance_theory", Column::real, 9},  // empty where infinite
                {"furnace_mean", Column::real, 9},
                {"furnace_mean_theory", Column::real, 9},
                {"scene_variance", Column::real, 9},
                {"scene_variance_vs_uniform", Column::real, 6},
                {"scene_mean", Column::real, 9},
                {"scene_seconds", Column::real, 6},           // both renders of the scene
                {"scene_rays", Column::integer}});
}

// equal_time.csv: the equal-sample pair, the equal-time cosine image and the reference.
Table equal_time_table() {
  return Table({{"image", Column::text},
                {"pdf", Column::text},
                {"spp", Column::integer},
                {"rays", Column::integer},
                {"seconds", Column::real, 6},
                {"relative_mse", Column::real, 9}});  // empty for the reference
}

// The importance-sampled path tracer as the pixel loop's estimator.
RenderResult render_with(const Scene& scene, const Camera& camera, const HemispherePdf& pdf,
                         int spp, std::uint64_t first_sample, const Options& o) {
  return render(camera, {spp, first_sample, o.common.seed, o.common.threads, nullptr},
                [&](const Ray& ray, Rng& rng, RayCount& count) {
                  return estimate_importance_path_radiance(scene, ray, o.depth, pdf, rng, count);
                });
}

// Two independent renders at spp (samples [0, spp) and [spp, 2 spp)) and the variance of one
// sample they measure, spp x mean of (A - B)^2 / 2. A is kept.
struct PairResult {
  RenderResult a;
  RenderTotals cost;
  double variance = 0.0;
};
PairResult render_pair(const Scene& scene, const Camera& camera, const HemispherePdf& pdf,
                       const Options& o) {
  PairResult pair{render_with(scene, camera, pdf, o.spp, 0, o), {}, 0.0};
  const RenderResult b =
      render_with(scene, camera, pdf, o.spp, static_cast<std::uint64_t>(o.spp), o);
  pair.cost = totals_of(pair.a);
  pair.cost.add(b);
  pair.variance = o.spp * two_render_mean_squared_error(pair.a.image, b.image);
  return pair;
}

void add_totals(RenderTotals& total, const RenderTotals& more) {
  total.rays += more.rays;
  total.non_finite_samples += more.non_finite_samples;
  total.seconds += more.seconds;
}

// Relative MSE of an image against a reference: the mean over pixels and channels of
// (A - R)^2 / (R^2 + 0.01); the 0.01 keeps black pixels from dominating (a common choice).
double relative_mse(const Image& a, const Image& reference) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[i][c], d = a.pixels[i][c] - r;
      sum += d * d / (r * r + 0.01);
    }
  return sum / (3.0 * static_cast<double>(a.pixels.size()));
}

// The study: one row per pdf; keeps each pdf's first scene image (A) for the outputs.
struct Study {
  Table variances = variance_table();
  std::vector<RenderResult> images;  // A of the scene, per pdf
  RenderTotals total;
};
Study run_study(const Scene& scene, const Camera& camera, const std::vector<HemispherePdf>& pdfs,
                const Options& o) {
  const SceneParams& f = o.scene.params;
  const Scene furnace = make_furnace(f.furnace_albedo, f.furnace_emission);
  const Camera furnace_camera(furnace.camera, k_furnace_side, k_furnace_side);
  ProgressBar progress("ch07 pdfs", pdfs.size(), o.common.quiet);
  Study study;
  double uniform_variance = std::nan("");
  for (const HemispherePdf& pdf : pdfs) {
    const PairResult in_furnace = render_pair(furnace, furnace_camera, pdf, o);
    PairResult in_scene = render_pair(scene, camera, pdf, o);
    if (pdf.kind == HemispherePdf::uniform) uniform_variance = in_scene.variance;
    const double theory =
        furnace_radiance_variance(pdf, f.furnace_albedo, f.furnace_emission, o.depth);
    study.variances.add_row(
        {pdf_name(pdf), pdf.kind == HemispherePdf::grazing ? Cell{} : Cell{pdf.m},
         in_furnace.variance, std::isfinite(theory) ? Cell{theory} : Cell{},
         mean_radiance(in_furnace.a.image),
         furnace_radiance(f.furnace_albedo, f.furnace_emission, o.depth), in_scene.variance,
         in_scene.variance / uniform_variance, mean_radiance(in_scene.a.image),
         in_scene.cost.seconds, in_scene.cost.rays});
    add_totals(study.total, in_furnace.cost);
    add_totals(study.total, in_scene.cost);
    study.images.push_back(std::move(in_scene.a));
    progress.advance();
  }
  progress.finish();
  return study;
}

// Equal time, with rays as the clock: the cosine image gets the samples that fit in the rays
// of the uniform image at spp (paths of the two pdfs escape the scene at different bounces, so
// their rays per sample differ). Rays make the count deterministic; the seconds are measured
// and written beside them.
int equal_time_spp(const RenderResult& uniform, const RenderResult& cosine, int spp) {
  const double ratio = static_cast<double>(uniform.rays) / static_cast<double>(cosine.rays);
  return std::clamp(static_cast<int>(std::lround(spp * ratio)), 1, 2 * spp);
}

// The reference: the closed form in the furnace, else the cosine pdf at --reference-spp on
// samples no other render uses.
RenderResult reference_image(const Scene& scene, const Camera& camera, const Options& o) {
  if (o.scene.scene == "furnace") {
    const SceneParams& f = o.scene.params;
    RenderResult exact;
    exact.image = Image(o.image.width, o.image.height,
                        Color(furnace_radiance(f.furnace_albedo, f.furnace_emission, o.depth)));
    return exact;
  }
  return render_with(scene, camera, cosine_power_pdf(1), o.reference_spp,
                     k_reference_first_sample, o);
}

// uniform and cosine at equal spp, cosine at equal time, each against the reference.
Table compare_at_equal_time(const Study& study, const Scene& scene, const Camera& camera,
                            const Options& o, RenderResult& cosine_equal_time,
                            RenderResult& reference) {
  const RenderResult& uniform = study.images[0];  // the pdfs start with m = 0, 1
  const RenderResult& cosine = study.images[1];
  const int spp_equal = equal_time_spp(uniform, cosine, o.spp);
  cosine_equal_time = render_with(scene, camera, cosine_power_pdf(1), spp_equal, 0, o);
  reference = reference_image(scene, camera, o);
  Table table = equal_time_table();
  const auto row = [&](const char* image, const char* pdf, int spp, const RenderResult& r) {
    table.add_row({image, pdf, spp, r.rays, r.seconds, relative_mse(r.image, reference.image)});
  };
  row("uniform", "uniform", o.spp, uniform);
  row("cosine", "cosine", o.spp, cosine);
  row("cosine_equal_time", "cosine", spp_equal, cosine_equal_time);
  const bool exact = o.scene.scene == "furnace";
  table.add_row({"reference", exact ? "closed form" : "cosine", exact ? 0 : o.reference_spp,
                 reference.rays, reference.seconds, Cell{}});
  return table;
}

void write_images(const Options& o, const Study& study, const std::vector<HemispherePdf>& pdfs,
                  const RenderResult& cosine_equal_time, const RenderResult& reference) {
  const auto write = [&](const std::string& stem, const Image& image) {
    write_png(o.common.out / (stem + ".png"), image);
    write_pfm(o.common.out / (stem + ".pfm"), image);
  };
  write("uniform", study.images[0].image);
  write("cosine", study.images[1].image);
  write("cosine_equal_time", cosine_equal_time.image);
  write("reference", reference.image);
  std::vector<Image> strip;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < pdfs.size(); ++i) {
    strip.push_back(study.images[i].image);
    labels.push_back(pdf_name(pdfs[i]));
  }
  strip.push_back(reference.image);
  labels.push_back("reference");
  write_png(o.common.out / "noise_strip.png",
            centre_detail_strip(strip, labels, fmt::format("at {} spp per pdf", o.spp)));
}

double cosine_furnace_variance(const Table& variances) {
  return variances.at(1, "furnace_variance").number();
}

void write_summary(const CLI::App& app, const Options& o, const Study& study,
                   const Table& equal_time, const RenderTotals& total) {
  Json summary = start_summary(k_chapter, o.common);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  summary["depth"] = o.depth;
  summary["furnace"] = {{"albedo", o.scene.params.furnace_albedo},
                        {"emission", o.scene.params.furnace_emission},
                        {"width", k_furnace_side},
                        {"height", k_furnace_side},
                        {"cosine_variance", cosine_furnace_variance(study.variances)}};
  add_render_totals(summary, total);
  summary["variance_vs_m"] = study.variances.json();
  summary["equal_time"] = equal_time.json();
  summary["flags"] = flags_json(app);
  write_json(o.common.out / "summary.json", summary);
}

void print_table(const Options& o, const Study& study, const Table& equal_time,
                 const RenderTotals& total) {
  fmt::print("{}  scene {}  {}x{}  {} spp  depth {}  {} threads\n", k_chapter.name,
             o.scene.scene, o.image.width, o.image.height, o.spp, o.depth, o.common.threads);
  fmt::print("  variance of one sample, per pixel (furnace: albedo {}, emission {}):\n",
             o.scene.params.furnace_albedo, o.scene.params.furnace_emission);
  fmt::print("{}", study.variances.console({"pdf", "furnace_variance", "furnace_variance_theory",
                                            "scene_variance", "scene_variance_vs_uniform"}));
  fmt::print("  furnace variance with the cosine pdf: {:.3g} (0 to rounding)\n",
             cosine_furnace_variance(study.variances));
  fmt::print("  against the reference:\n{}",
             equal_time.console({"image", "spp", "rays", "seconds", "relative_mse"}));
  fmt::print("  rays traced {} in {:.2f} s: {:.4g} rays/s;  non-finite samples {}\n", total.rays,
             total.seconds, total.rays_per_second(), total.non_finite_samples);
  fmt::print("  wrote {}/{{uniform,cosine,cosine_equal_time,reference}}.{{png,pfm}}, "
             "noise_strip.png, variance_vs_m.csv,.png, equal_time.csv, summary.json\n",
             o.common.out.string());
}

int run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  check_ray_limit(predicted_work(o), k_max_rays, "--spp, --reference-spp, --depth, --width, --height",
                  o.common.threads, "lower one of them");
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  const std::vector<HemispherePdf> pdfs = study_pdfs(o.powers);
  prepare_output_dir(o.common.out);

  const Study study = run_study(scene, camera, pdfs, o);
  RenderResult cosine_equal_time, reference;
  const Table equal_time =
      compare_at_equal_time(study, scene, camera, o, cosine_equal_time, reference);
  RenderTotals total = study.total;
  total.add(cosine_equal_time);
  total.add(reference);

  write_images(o, study, pdfs, cosine_equal_time, reference);
  write_csv(o.common.out / "variance_vs_m.csv", study.variances);
  write_csv(o.common.out / "equal_time.csv", equal_time);
  write_variance_plot(o.common.out, o.scene.scene, o.spp);
  write_summary(app, o, study, equal_time, total);
  if (!o.common.quiet) print_table(o, study, equal_time, total);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image);
  app.add_option("--spp", o.spp, "Samples per pixel of every image of the study")
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--depth", o.depth, "Bounces after the first hit (0: emitted light only)")
      ->check(CLI::Range(0, 1000));
  add_list_option(app, "--powers", o.powers,
                  "The powers m of p ~ cos^m(theta) to compare (a list: 0,1,2,4,8; 0 uniform "
                  "and 1 cosine are always in)", 0, 64);
  app.add_option("--reference-spp", o.reference_spp,
                 "Samples per pixel of the cosine reference image (not used in the furnace)")
      ->check(CLI::Range(1, 1 << 16));
  return app.run(argc, argv, [&] { return run(app, o); });
}
