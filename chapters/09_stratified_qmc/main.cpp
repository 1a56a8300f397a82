// Chapter 09: stratified and quasi-Monte Carlo sampling. Chapter 02's error fell as N^-1/2
// whatever we did; chapter 03's grid beat it in one dimension and lost in many. Can we
// *place* the N points better than at random, keep the estimate unbiased, and beat N^-1/2?
//
//   for each point set P (independent, jittered, Latin hypercube, Sobol' xor-shifted and
//   Owen-scrambled, Halton), each N and each randomisation r < R:
//     F_N = vol/N sum_{i<N} f(a + (b - a) u_i),   u_i the i-th point of P for key r
//   rms error over the R randomisations against N: -1/2 for independent points, -3/4 for
//   strata on the disk's edge, -1 (jittered) and -3/2 (Owen-scrambled Sobol', N = 2^m) on a
//   smooth integrand; and at one budget against the dimension k, where the gain fades.
//
// With --render-max-spp, the same idea in chapter 05's path tracer (render_study.hpp): each
// pixel's samples drawn from independent streams, jittered or Owen-scrambled Sobol' 2D sets
// padded per bounce (--sampler), the rms error against spp at depth 1 and at full depth.
//
// The point sets are in common/sampling/point_sets.hpp (each point alone is uniform: E[F_N] =
// I); the studies in plan.hpp, the tables in tables.hpp, the figures in plots.hpp, the
// console and summary.json in report.hpp.

#include <cstdint>
#include <span>
#include <vector>

#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/stopwatch.hpp"
#include "integration/compensated_sum.hpp"
#include "integration/domain.hpp"
#include "io/output.hpp"
#include "app/summary.hpp"
#include "app/usage_error.hpp"
#include "plan.hpp"
#include "plots.hpp"
#include "render_study.hpp"
#include "render_study_flags.hpp"
#include "report.hpp"
#include "tables.hpp"

using namespace mcrt;
using namespace mcrt::ch09;

namespace {

const Chapter k_chapter{"ch09_stratified_qmc",
                        "Chapter 09: stratified and quasi-Monte Carlo sampling. The rms error "
                        "against N of independent, jittered, Latin hypercube, scrambled Sobol' "
                        "and Halton points on the disk and on a smooth integrand, and at a fixed "
                        "budget against the dimension D."};

// F_N = vol/N sum_{i<N} f(x_i), x_i = a + (b - a) u_i: chapter 03's Monte Carlo estimator with
// the points u_i of a set in place of independent draws. Unbiased whenever each u_i alone is
// uniform on [0,1)^k, which every randomised set here guarantees.
template <class F, class Points>
double estimate_with_points(const F& f, const Box& box, const Points& points, std::uint32_t n) {
  CompensatedSum sum;  // at N = 2^20 the error sought (1e-9) is near a plain sum's rounding
  BoxPoint x{};
  for (std::uint32_t i = 0; i < n; ++i) {
    for (int j = 0; j < box.dims; ++j)
      x[j] = box.lower[j] + (box.upper[j] - box.lower[j]) * points(i, static_cast<unsigned>(j));
    sum.add(f(std::span<const double>(x.data(), static_cast<std::size_t>(box.dims))));
  }
  return box.volume() * sum.value() / n;
}

struct Options {
  CommonOptions common;
  int trials = 16;                  // randomisations R per N: the rms error is over these
  std::uint32_t max_n = 1u << 16;   // the largest N of the disk and smooth studies
  std::uint32_t budget = 1u << 16;  // N of the dimension study at every k: 2^16 = 2^k at k = 16
  std::vector<int> dims = {1, 2, 3, 4, 5, 6, 8, 10, 12, 14, 16};  // k of the dimension study
  int picture_points = 64;    // points of each set in point_sets.png
  RenderStudyOptions render;  // the path tracer's samplers: off unless --render-max-spp
};

// Every task (one randomisation of one series at one N) on any core, largest first; each
// writes only its own estimate, from points keyed by the task: the same whatever --threads.
std::vector<double> run_tasks(const Plan& plan, const Options& o) {
  std::vector<double> estimates(plan.tasks.size());
  ProgressBar progress("ch09 sampling", static_cast<std::uint64_t>(plan.points), o.common.quiet);
  parallel_for(plan.schedule.size(), o.common.threads, [&](std::size_t s) {
    const Task& task = plan.tasks[plan.schedule[s]];
    const Series& series = plan.series[task.series];
    const std::uint64_t key = points_key(o.common.seed, plan, task);
    estimates[plan.schedule[s]] =
        with_integrand(series.study, series.dims, [&](const auto& f, const auto& box) {
          return with_points(series.sampler, task.n, static_cast<unsigned>(series.dims), key,
                             [&](const auto& points) {
                               return estimate_with_points(f, box, points, task.n);
                             });
        });
    progress.advance(task.n);
  });
  progress.finish();
  return estimates;
}

// The picture: the first --picture-points points of each set in 2D, for one key.
Table picture_points(const Options& o) {
  Table table({text("sampler"), real("x", 6, Column::fixed), real("y", 6, Column::fixed)});
  const auto n = static_cast<std::uint32_t>(o.picture_points);
  for (Sampler sampler : k_samplers)
    with_points(sampler, n, 2, hash_bits(o.common.seed, ~std::uint64_t{0}, 0), [&](const auto& p) {
      for (std::uint32_t i = 0; i < n; ++i) table.add_row({name_of(sampler), p(i, 0), p(i, 1)});
      return 0;
    });
  return table;
}

void run(const CLI::App& app, const Options& o) {
  const Plan plan = make_plan(o.max_n, o.budget, o.dims, o.trials, o.common.threads);
  const Stopwatch clock;
  const std::vector<double> estimates = run_tasks(plan, o);
  const Tables t = tabulate(plan, estimates, o.trials, o.budget);
  const RenderStudy render =
      run_render_study(o.render, o.common.seed, o.common.threads, o.common.quiet);
  const double seconds = clock.seconds();

  write_csv(o.common.dir / "disk.csv", t.disk);
  write_csv(o.common.dir / "smooth.csv", t.smooth);
  write_csv(o.common.dir / "slopes.csv", t.slopes);
  write_csv(o.common.dir / "dimension.csv", t.dimension);
  write_csv(o.common.dir / "points.csv", picture_points(o));
  write_plot(o.common.dir,
             error_plot("disk", t.disk, t.slopes, "Unit disk in [-1,1]^2 (4 x the indicator)"));
  write_plot(o.common.dir, error_plot("smooth", t.smooth, t.slopes, "e^{-|x|^2} on [0,1]^2"));
  write_plot(o.common.dir, dimension_plot(o.budget, t.dimension));
  write_plot(o.common.dir, point_sets_plot(o.picture_points));
  Json summary = summary_of(k_chapter, app, o, plan, t);
  write_render_study(o.common.dir, o.render, render, summary, o.common.quiet);
  write_json(o.common.dir / "summary.json", summary);
  write_timings(o.common.dir, timings_of(k_chapter, o, plan, seconds), run_flags_json(app));
  if (!o.common.quiet) print_report(k_chapter, o, plan, t, seconds);
}

// A power of two from `lowest` to 2^24, or a usage error naming the flag.
void check_power_of_two(const char* flag, std::uint32_t n, std::uint32_t lowest) {
  if (n < lowest || (n & (n - 1)) != 0)
    throw UsageError(
        fmt::format("{} {}: give a power of two from {} to {} (Sobol' nets have 2^m points)", flag,
                    n, lowest, 1u << 24));
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  std::uint64_t max_n = o.max_n, budget = o.budget;
  add_number_option(app, "--trials", o.trials,
                    "Randomisations K per N (2 or more: the rms error is over these)", 2, 100000);
  add_number_option(app, "--max-n", max_n,
                    "Largest N of the disk and smooth studies, a power of two (N = 16, 32, ...)",
                    std::uint64_t{64}, std::uint64_t{1} << 24);
  add_number_option(app, "--budget", budget, "N of the dimension study at every D, a power of two",
                    std::uint64_t{16}, std::uint64_t{1} << 24);
  add_list_option(app, "--dims", o.dims, "Dimensions D of the dimension study, e.g. 1,2,4,8", 1,
                  k_max_box_dims);
  add_number_option(app, "--picture-points", o.picture_points,
                    "Points of each set drawn in point_sets.png", 1, 4096);
  std::string sampler_choice = "all";
  add_render_study_options(app, o.render, sampler_choice);
  return app.run(argc, argv, [&] {
    o.max_n = static_cast<std::uint32_t>(max_n);
    o.budget = static_cast<std::uint32_t>(budget);
    check_power_of_two("--max-n", o.max_n, 64);  // N = 16, 32, 64: a slope and its error
    check_power_of_two("--budget", o.budget, 16);
    check_render_study(o.render, sampler_choice, o.common);
    run(app, o);
  });
}
