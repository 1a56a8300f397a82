// Chapter 04: the recursive N^k estimator, and why it cannot be the answer.
//
//   for each N in --branching, for each k = 0..--max-depth:
//     image = render with incidentRadiance (N branches per hit, cut at depth k)
//     record its rays (closest-hit queries), its time and its mean radiance
//   limit = the mean radiance with N = 1 cut far deeper: what every cut at k is missing
//   at one ray budget per pixel: N = 1 with many camera samples against N > 1 with few
//
// The estimator is common/recursive_estimator.hpp, written as the lecture's pseudo-code. Its
// three problems become numbers: the rays grow as N^k, the cut at depth k drops the light of
// longer paths, and branching is a poor way to spend rays against noise.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/cli.hpp"
#include "io/contact_sheet.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "io/summary.hpp"
#include "render/recursive_estimator.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

using namespace mcrt;

namespace {

// The light missing at depth k is measured with N = 1 (at most k + 1 rays a sample) and many
// samples, at every k and at a depth deep enough to stand for the limit: this one, or twice
// --max-depth if that is deeper. In the Cornell box no surface keeps more than 0.73 of the
// light it receives, so paths longer than 32 bounces carry under 0.73^33 ~ 3e-5 of it. All
// these renders share their random numbers (same seed and streams), and with N = 1 the path
// cut at k + 1 extends the path cut at k, so their differences are far less noisy than they.
constexpr int k_limit_depth = 32;
constexpr int k_light_spp = 64;
// The speed quoted when a run is refused (no work has been done yet to measure one): what
// bench_recursive_estimator measured for the Cornell box on one core of the machine these
// chapters were written on (2.6-2.9 million rays per second).
constexpr double k_estimated_rays_per_second_per_thread = 2.5e6;

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
};

template <class... Args>
std::string format(const char* pattern, Args... args) {
  const int size = std::snprintf(nullptr, 0, pattern, args...);
  std::string text(static_cast<std::size_t>(size), '\0');
  std::snprintf(text.data(), text.size() + 1, pattern, args...);
  return text;
}

// Every render of the run and its predicted ray count (no escapes), known before any work.
struct Plan {
  std::uint64_t pixels = 0;
  int limit_depth = 0;
  std::vector<int> equal_cost_spp;  // per N: budget / rays per sample; 0 when one is over
  double predicted_rays = 0.0;      // a double: the request may exceed 2^64
};

Plan make_plan(const Options& o) {
  Plan plan;
  plan.pixels = static_cast<std::uint64_t>(o.image.width) * o.image.height;
  plan.limit_depth = std::max(k_limit_depth, 2 * o.max_depth);
  const auto rays = [&](int n, int k, int spp) {
    return static_cast<double>(plan.pixels) * spp *
           static_cast<double>(max_rays_per_sample(n, k));
  };
  for (int n : o.branching)
    for (int k = 0; k <= o.max_depth; ++k) plan.predicted_rays += rays(n, k, o.spp);
  for (int k = 0; k <= o.max_depth; ++k) plan.predicted_rays += rays(1, k, k_light_spp);
  plan.predicted_rays += rays(1, plan.limit_depth, k_light_spp);
  for (int n : o.branching) {
    const std::uint64_t per_sample = max_rays_per_sample(n, o.equal_cost_depth);
    const auto spp = static_cast<int>(static_cast<std::uint64_t>(o.budget) / per_sample);
    plan.equal_cost_spp.push_back(spp);
    plan.predicted_rays += 2.0 * rays(n, o.equal_cost_depth, spp);  // two independent renders
  }
  return plan;
}

// Refuses impossible work before any is done: exit code 2 with the flag, the predicted count
// and how long it would take.
void check_plan(const Options& o, const Plan& plan) {
  if (o.branching.empty()) throw UsageError("--branching: give at least one N >= 1");
  const int cheapest = o.branching.front();  // sorted: the smallest N
  const std::uint64_t cheapest_sample = max_rays_per_sample(cheapest, o.equal_cost_depth);
  if (static_cast<std::uint64_t>(o.budget) < cheapest_sample)
    throw UsageError(format("--budget: %d rays per pixel cannot pay for one sample at "
                            "--equal-cost-depth %d (N = %d needs %llu); give at least that",
                            o.budget, o.equal_cost_depth, cheapest,
                            static_cast<unsigned long long>(cheapest_sample)));
  if (plan.predicted_rays > o.max_rays) {
    const double seconds =
        plan.predicted_rays / (k_estimated_rays_per_second_per_thread * o.common.threads);
    throw UsageError(format(
        "--max-rays: this run would trace up to %.3g rays (sweep, missing-light and equal-cost "
        "renders), about %.3g s at an estimated %.3g rays/s per thread on %d threads, above "
        "the limit of %.3g; lower --max-depth, --branching, --spp, --budget or the image size, "
        "or raise --max-rays",
        plan.predicted_rays, seconds, k_estimated_rays_per_second_per_thread, o.common.threads,
        o.max_rays));
  }
}

// One image of the recursion: every camera sample is incidentRadiance(camera ray), depth 0.
// The progress bar counts each sample's predicted rays, so it moves with the work.
RenderResult render_recursive(const Scene& scene, const Camera& camera,
                              const RecursiveSettings& recursion, int spp,
                              std::uint64_t first_sample, const Options& o,
                              ProgressBar& progress) {
  const std::uint64_t sample_rays = max_rays_per_sample(recursion.branching, recursion.max_depth);
  const RenderSettings settings{spp, first_sample, o.common.seed, o.common.threads, nullptr};
  return render(camera, settings, [&](const Ray& ray, Rng& rng, RayCount& count) {
    const Color L = incident_radiance(scene, ray, 0, recursion, rng, count);
    progress.advance(sample_rays);
    return L;
  });
}

struct SweepRow {
  int branching = 1;
  int depth = 0;
  std::uint64_t rays = 0;
  std::uint64_t predicted_max_rays = 0;
  double seconds = 0.0;
  double rays_per_second = 0.0;
  double mean_radiance = 0.0;
  Image image;
};

struct EqualCostRow {
  int branching = 1;
  int spp = 0;
  std::uint64_t predicted_rays_per_pixel = 0;
  double rays_per_pixel = 0.0;  // traced by one of the two renders
  double seconds = 0.0;         // both renders
  double mean_radiance = 0.0;
  double rms_error = 0.0;
  double relative_rms_error = 0.0;
  double rms_error_at_budget = 0.0;  // scaled to exactly --budget rays per pixel
};

// Two independent renders A, B of one estimator: E[(A - B)^2] = 2 Var per pixel and channel,
// so the RMS error of one render is sqrt(mean (A - B)^2 / 2), with no reference image (and no
// reference noise) needed.
double rms_error_of_pair(const Image& a, const Image& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const Color d = a.pixels[i] - b.pixels[i];
    sum += glm::dot(d, d);
  }
  return std::sqrt(sum / (2.0 * 3.0 * static_cast<double>(a.pixels.size())));
}

std::string join(const std::vector<int>& values, const char* separator) {
  std::string text;
  for (int v : values) text += (text.empty() ? "" : separator) + std::to_string(v);
  return text;
}

void write_rays_csv(const Options& o, const std::vector<SweepRow>& sweep) {
  std::string csv = "branching,depth,rays,predicted_max_rays,seconds,rays_per_second,"
                    "mean_radiance\n";
  for (const SweepRow& r : sweep)
    csv += format("%d,%d,%llu,%llu,%.6g,%.6g,%.9g\n", r.branching, r.depth,
                  static_cast<unsigned long long>(r.rays),
                  static_cast<unsigned long long>(r.predicted_max_rays), r.seconds,
                  r.rays_per_second, r.mean_radiance);
  write_file_atomic(o.common.out / "rays.csv", csv);
}

void write_missing_light_csv(const Options& o, const std::vector<double>& mean_by_depth,
                             double limit) {
  std::string csv = "depth,mean_radiance,limit_mean_radiance,missing_fraction\n";
  for (std::size_t k = 0; k < mean_by_depth.size(); ++k)
    csv += format("%zu,%.9g,%.9g,%.6g\n", k, mean_by_depth[k], limit,
                  limit > 0.0 ? 1.0 - mean_by_depth[k] / limit : 0.0);
  write_file_atomic(o.common.out / "missing_light.csv", csv);
}

void write_equal_cost_csv(const Options& o, const std::vector<EqualCostRow>& rows) {
  std::string csv = "branching,depth,spp,predicted_rays_per_pixel,rays_per_pixel,seconds,"
                    "mean_radiance,rms_error,relative_rms_error,rms_error_at_budget\n";
  for (const EqualCostRow& r : rows)
    csv += format("%d,%d,%d,%llu,%.9g,%.6g,%.9g,%.9g,%.9g,%.9g\n", r.branching,
                  o.equal_cost_depth, r.spp,
                  static_cast<unsigned long long>(r.predicted_rays_per_pixel), r.rays_per_pixel,
                  r.seconds, r.mean_radiance, r.rms_error, r.relative_rms_error,
                  r.rms_error_at_budget);
  write_file_atomic(o.common.out / "equal_cost.csv", csv);
}

void write_plots(const Options& o, double limit, int limit_depth) {
  // One line per N, picked out of rays.csv by its first column.
  const std::string per_n = "Ns = '" + join(o.branching, " ") + "'\nset xtics 1\n";
  const std::string column_of_n = "(column(1) == word(Ns, i) + 0 ? column(%d) : NaN)";
  write_plot(o.common.out,
             {"rays_vs_depth",
              "Rays traced against depth: N^k grows as a straight line of slope log N",
              "depth k", "rays traced", false, true, per_n + "set key top left\n",
              "plot for [i=1:words(Ns)] 'rays.csv' using 2:" + format(column_of_n.c_str(), 3) +
                  " with linespoints pt 7 lw 2 lc i title 'N = '.word(Ns, i), "
                  "for [i=1:words(Ns)] 'rays.csv' using 2:" + format(column_of_n.c_str(), 4) +
                  " with lines dt 2 lc i title 'N = '.word(Ns, i).' predicted (no escapes)'"});
  write_plot(o.common.out,
             {"mean_radiance_vs_depth",
              "Mean radiance against depth: the cut at k drops the light of longer paths",
              "depth k", "mean radiance of the image", false, false,
              per_n + format("limit = %.9g\nset key bottom right\nset yrange [0:*]\n"
                             "set offsets 0, 0, graph 0.1, 0\n",
                             limit),
              "plot for [i=1:words(Ns)] 'rays.csv' using 2:" + format(column_of_n.c_str(), 7) +
                  " with linespoints pt 7 lw 2 lc i title 'N = '.word(Ns, i).', " +
                  std::to_string(o.spp) + " spp', " +
                  format("'missing_light.csv' using 1:2 with linespoints pt 5 lw 3 lc 'black' "
                         "title 'N = 1, %d spp', limit with lines dt 2 lw 2 lc 'black' "
                         "title 'limit (N = 1, k = %d, %d spp)'",
                         k_light_spp, limit_depth, k_light_spp)});
  write_plot(o.common.out,
             {"equal_cost",
              format("Equal cost: %d rays per pixel at depth %d", o.budget, o.equal_cost_depth),
              "branching N", "RMS error at the budget", true, true,
              "set key top left\nset format x '%g'\nset xtics (" + join(o.branching, ", ") +
                  ")\n" + format("set xrange [0.8:%g]\n", 1.25 * o.branching.back()),
              "plot 'equal_cost.csv' using 1:10 with linespoints pt 7 lw 2 title 'RMS error'"});
}

// Small images are blown up (nearest neighbour, so the noise stays visible) to about 256 wide.
void write_grid(const Options& o, const std::vector<SweepRow>& sweep) {
  const int factor = std::clamp(256 / o.image.width, 1, 4);
  std::vector<Image> images;
  images.reserve(sweep.size());
  for (const SweepRow& r : sweep) images.push_back(upscale_nearest(r.image, factor));
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < sweep.size(); ++i)
    cells.push_back({&images[i], format("N=%d k=%d", sweep[i].branching, sweep[i].depth)});
  SheetLayout layout;
  layout.columns = o.max_depth + 1;
  layout.label_scale = o.image.width * factor >= 120 ? 2 : 1;
  layout.title = format("rows: N = %s   columns: depth k = 0..%d   %d spp",
                        join(o.branching, ",").c_str(), o.max_depth, o.spp);
  write_png(o.common.out / "grid.png", make_contact_sheet(cells, layout));
}

int run(const CLI::App& app, Options& o) {
  check_image_size(o.image);
  std::sort(o.branching.begin(), o.branching.end());
  o.branching.erase(std::unique(o.branching.begin(), o.branching.end()), o.branching.end());
  const Plan plan = make_plan(o);
  check_plan(o, plan);
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  prepare_output_dir(o.common.out);

  ProgressBar progress("ch04 sweep", static_cast<std::uint64_t>(plan.predicted_rays),
                       o.common.quiet);
  std::uint64_t total_rays = 0, non_finite = 0;
  double total_seconds = 0.0;
  const auto account = [&](const RenderResult& r) {
    total_rays += r.rays;
    non_finite += r.non_finite_samples;
    total_seconds += r.seconds;
  };

  // 1. The explosion, and 3. the images: every N, every k.
  std::vector<SweepRow> sweep;
  for (int n : o.branching) {
    for (int k = 0; k <= o.max_depth; ++k) {
      RenderResult r = render_recursive(scene, camera, {n, k}, o.spp, 0, o, progress);
      account(r);
      const double mean = mean_radiance(r.image);
      sweep.push_back({n, k, r.rays, plan.pixels * o.spp * max_rays_per_sample(n, k), r.seconds,
                       r.rays_per_second(), mean, std::move(r.image)});
    }
  }
  // 2. The missing light, measured closely: N = 1 with many samples at every k, and deep.
  std::vector<double> mean_by_depth;
  for (int k = 0; k <= o.max_depth; ++k) {
    const RenderResult r = render_recursive(scene, camera, {1, k}, k_light_spp, 0, o, progress);
    account(r);
    mean_by_depth.push_back(mean_radiance(r.image));
  }
  const RenderResult limit_render =
      render_recursive(scene, camera, {1, plan.limit_depth}, k_light_spp, 0, o, progress);
  account(limit_render);
  const double limit = mean_radiance(limit_render.image);

  // 4. Equal cost: the same rays per pixel spent on camera samples (N = 1) or on branches.
  std::vector<EqualCostRow> equal_cost;
  for (std::size_t i = 0; i < o.branching.size(); ++i) {
    const int n = o.branching[i], spp = plan.equal_cost_spp[i];
    if (spp == 0) continue;  // one sample of this N costs more than the budget
    const RecursiveSettings recursion{n, o.equal_cost_depth};
    const RenderResult a = render_recursive(scene, camera, recursion, spp, 0, o, progress);
    const RenderResult b = render_recursive(scene, camera, recursion, spp, spp, o, progress);
    account(a);
    account(b);
    EqualCostRow row;
    row.branching = n;
    row.spp = spp;
    row.predicted_rays_per_pixel = spp * max_rays_per_sample(n, o.equal_cost_depth);
    row.rays_per_pixel = static_cast<double>(a.rays) / static_cast<double>(plan.pixels);
    row.seconds = a.seconds + b.seconds;
    row.mean_radiance = 0.5 * (mean_radiance(a.image) + mean_radiance(b.image));
    row.rms_error = rms_error_of_pair(a.image, b.image);
    row.relative_rms_error = row.mean_radiance > 0.0 ? row.rms_error / row.mean_radiance : 0.0;
    // Variance falls as 1/spp, so error scales as 1/sqrt(rays) at a fixed N.
    row.rms_error_at_budget = row.rms_error * std::sqrt(row.rays_per_pixel / o.budget);
    equal_cost.push_back(row);
  }
  progress.finish();

  const auto by_error = [](const EqualCostRow& x, const EqualCostRow& y) {
    return x.rms_error_at_budget < y.rms_error_at_budget;
  };
  const EqualCostRow& best = *std::min_element(equal_cost.begin(), equal_cost.end(), by_error);
  const EqualCostRow& worst = *std::max_element(equal_cost.begin(), equal_cost.end(), by_error);
  const std::string conclusion =
      format("At equal cost (%d rays per pixel, depth %d) N = %d with %d spp has the smallest "
             "error, %.3g; N = %d with %d spp has %.2fx more. %s",
             o.budget, o.equal_cost_depth, best.branching, best.spp, best.rms_error_at_budget,
             worst.branching, worst.spp,
             best.rms_error_at_budget > 0.0 ? worst.rms_error_at_budget / best.rms_error_at_budget
                                            : 1.0,
             best.branching == 1 ? "Spend rays on camera samples, not on branches: one path per "
                                   "sample is chapter 05's path tracer."
                                 : "Here branching paid off.");

  write_rays_csv(o, sweep);
  write_missing_light_csv(o, mean_by_depth, limit);
  write_equal_cost_csv(o, equal_cost);
  write_plots(o, limit, plan.limit_depth);
  write_grid(o, sweep);

  Json summary;
  summary["chapter"] = "ch04_recursive_nk";
  summary["scene"] = o.scene.scene;
  summary["width"] = o.image.width;
  summary["height"] = o.image.height;
  summary["spp"] = o.spp;
  summary["branching"] = o.branching;
  summary["max_depth"] = o.max_depth;
  summary["seed"] = o.common.seed;
  summary["threads"] = o.common.threads;
  summary["predicted_max_rays"] = plan.predicted_rays;
  summary["rays"] = total_rays;
  summary["seconds"] = total_seconds;
  summary["rays_per_second"] =
      total_seconds > 0.0 ? static_cast<double>(total_rays) / total_seconds : 0.0;
  summary["non_finite_samples"] = non_finite;
  Json sweep_json = Json::array();
  for (const SweepRow& r : sweep)
    sweep_json.push_back({{"branching", r.branching}, {"depth", r.depth}, {"rays", r.rays},
                          {"predicted_max_rays", r.predicted_max_rays}, {"seconds", r.seconds},
                          {"rays_per_second", r.rays_per_second},
                          {"mean_radiance", r.mean_radiance}});
  summary["sweep"] = sweep_json;
  Json missing = Json::array();
  for (std::size_t k = 0; k < mean_by_depth.size(); ++k)
    missing.push_back({{"depth", k}, {"mean_radiance", mean_by_depth[k]},
                       {"missing_fraction", limit > 0.0 ? 1.0 - mean_by_depth[k] / limit : 0.0}});
  summary["limit"] = {{"branching", 1}, {"depth", plan.limit_depth}, {"spp", k_light_spp},
                      {"mean_radiance", limit}};
  summary["missing_light"] = missing;
  Json equal_json = Json::array();
  for (const EqualCostRow& r : equal_cost)
    equal_json.push_back({{"branching", r.branching}, {"spp", r.spp},
                          {"rays_per_pixel", r.rays_per_pixel}, {"rms_error", r.rms_error},
                          {"rms_error_at_budget", r.rms_error_at_budget}});
  summary["equal_cost"] = {{"budget_rays_per_pixel", o.budget},
                           {"depth", o.equal_cost_depth},
                           {"best_branching", best.branching},
                           {"rows", equal_json},
                           {"conclusion", conclusion}};
  summary["flags"] = flags_json(app);
  write_json(o.common.out / "summary.json", summary);

  if (!o.common.quiet) {
    std::printf("ch04_recursive_nk  scene %s  %dx%d  %d spp  %d threads\n",
                o.scene.scene.c_str(), o.image.width, o.image.height, o.spp, o.common.threads);
    std::printf("%4s %3s %14s %14s %9s %10s %10s %8s\n", "N", "k", "rays", "predicted",
                "seconds", "rays/s", "mean L", "missing");
    for (const SweepRow& r : sweep)
      std::printf("%4d %3d %14llu %14llu %9.3f %10.3g %10.4f %7.1f%%\n", r.branching, r.depth,
                  static_cast<unsigned long long>(r.rays),
                  static_cast<unsigned long long>(r.predicted_max_rays), r.seconds,
                  r.rays_per_second, r.mean_radiance,
                  limit > 0.0 ? 100.0 * (1.0 - mean_by_depth[r.depth] / limit) : 0.0);
    std::printf("missing: 1 - mean L(k) / limit, both with N = 1 and %d spp; limit (k = %d): "
                "mean L %.4f\n", k_light_spp, plan.limit_depth, limit);
    std::printf("equal cost: %d rays per pixel, depth %d\n", o.budget, o.equal_cost_depth);
    std::printf("%4s %6s %11s %11s %11s %9s\n", "N", "spp", "rays/pixel", "rms error",
                "at budget", "relative");
    for (const EqualCostRow& r : equal_cost)
      std::printf("%4d %6d %11.1f %11.4g %11.4g %8.1f%%\n", r.branching, r.spp, r.rays_per_pixel,
                  r.rms_error, r.rms_error_at_budget, 100.0 * r.relative_rms_error);
    std::printf("%s\n", conclusion.c_str());
    std::printf("total: %llu rays in %.2f s (%.3g rays/s)\n",
                static_cast<unsigned long long>(total_rays), total_seconds,
                total_seconds > 0.0 ? static_cast<double>(total_rays) / total_seconds : 0.0);
    std::printf("wrote %s/{rays,missing_light,equal_cost}.csv, grid.png, plots, summary.json\n",
                o.common.out.string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Chapter 04: the recursive N^k estimator. At every hit N new directions, each "
               "followed recursively to depth k: counts the rays (N^k), the light lost by "
               "cutting at k, and compares branching with camera samples at equal cost.",
               "ch04_recursive_nk"};
  Options o;
  add_common_options(app, o.common, Chapter{"ch04_recursive_nk", ""});
  add_scene_options(app, o.scene);
  add_image_options(app, o.image);
  app.add_option("--spp", o.spp, "Camera samples per pixel in the sweep")
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--branching", o.branching, "Branching factors N, comma separated (each >= 1)")
      ->delimiter(',')
      ->check(CLI::Range(1, 1 << 16));
  app.add_option("--max-depth", o.max_depth, "Largest depth k of the sweep (0 = emission only)")
      ->check(CLI::Range(0, 64));
  app.add_option("--max-rays", o.max_rays,
                 "Refuse runs predicted to trace more rays than this (e.g. 2e9)")
      ->check(CLI::Range(1.0, 1e15));
  app.add_option("--equal-cost-depth", o.equal_cost_depth,
                 "Depth k of the equal-cost comparison")
      ->check(CLI::Range(0, 64));
  app.add_option("--budget", o.budget, "Rays per pixel of each equal-cost render")
      ->check(CLI::Range(1, 1 << 20));
  return run_chapter(app, argc, argv, [&] { return run(app, o); });
}
