// Chapter 03: the trapezoid rule against Monte Carlo, in one dimension and in k.
//
//   for each integrand f with known I (e^{-x^2}, ceil(sin x^2), e^{-|x|^2} and the unit
//   ball in k dimensions):
//     for n on a log grid:  T = sum over the n^k grid points of w_1...w_k f(x)     N = n^k
//                           error |T - I| = O(N^(-2/k)) smooth, O(N^(-1/k)) where f jumps
//     for N on a log grid:  F_N = vol/N sum_i f(X_i), X_i uniform, `trials` times
//                           rms error sqrt(V[F_N]) = O(N^(-1/2)) in every dimension
//     fit the slope of log(error) against log(N), beside the slope theory predicts
//
// The studies, their grids and the checks on the work are in study_plan.hpp; the figures in
// plots.hpp; summary.json, timings.json and the console in report.hpp.

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/parallel.hpp"
#include "core/stopwatch.hpp"
#include "integration/convergence.hpp"
#include "integration/error_study.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/quadrature.hpp"
#include "app/memory_limit.hpp"
#include "io/output.hpp"
#include "app/summary.hpp"
#include "io/table.hpp"
#include "plots.hpp"
#include "report.hpp"
#include "study_plan.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch03_trapezoid_vs_mc",
                        "Chapter 03: the trapezoid rule against Monte Carlo. Error against the "
                        "number of function evaluations N for smooth and discontinuous "
                        "integrands in 1 and k dimensions, and the fitted convergence slopes."};

struct Options {
  CommonOptions common;
  int trials = 16;                                   // Monte Carlo runs per N: rmse over these
  std::uint64_t max_evaluations = 1 << 20;           // N of the largest point of every study
  std::vector<int> dims = {1, 2, 3, 4, 5, 6, 7, 8};  // the k of the k-dimensional integrands
};

constexpr int k_max_dims = 12;  // 3^12 = 531441 evaluations at least
constexpr std::uint64_t k_max_budget = 1'000'000'000;
// Trial t at the Monte Carlo size `index` of study `study` draws from stream (study, index, t).
constexpr std::uint64_t k_studies = 256, k_indices = 1000, k_trials = 1ull << 32;

// T, or the mean of the trials' F_N and their rmse = sqrt(mean (F_N - I)^2).
struct Estimate {
  double value = 0.0, rmse = 0.0;
};

Estimate estimate(const Study& study, const Task& task, const Options& o, ProgressBar& progress) {
  return with_integrand(study, [&](const auto& f, const auto& domain) {
    if (task.trapezoid) {
      const double t = trapezoid(f, domain, task.n);
      progress.advance(task.evaluations);
      return Estimate{t, 0.0};
    }
    const ErrorStats e = repeated_estimates(
        task.n, o.trials, f.reference(), o.common.seed, 1, progress,
        [&](std::uint64_t n, Rng& rng) { return monte_carlo(f, domain, n, rng).estimate; },
        [&](std::uint64_t t) {
          return stream_key({{task.study, k_studies}, {task.index, k_indices}, {t, k_trials}});
        });
    return Estimate{e.mean(), e.rmse()};
  });
}

Column text(const char* name) { return {name, Column::text}; }
Column integer(const char* name) { return {name, Column::integer}; }
Column real(const char* name, int digits, Column::Style style) {
  return {name, Column::real, digits, style};
}

// What the run found: errors.csv, slopes.csv, budget.csv (each k-dimensional study's error at
// the largest N, the fixed budget) and each slope's guide line for the plots.
struct Results {
  Table errors{{text("integrand"), integer("dims"), text("method"), integer("points_per_axis"),
                integer("evaluations"), real("estimate", 17, Column::general),
                real("reference", 17, Column::general), real("abs_error", 6, Column::scientific),
                real("rmse", 6, Column::scientific)}};
  Table slopes{{text("integrand"), integer("dims"), text("method"),
                real("fitted_slope", 6, Column::fixed), real("standard_error", 6, Column::fixed),
                real("theory_slope", 6, Column::fixed), integer("points")}};
  Table budget{{text("integrand"), integer("dims"), real("reference", 17, Column::general),
                integer("points_per_axis"), integer("trapezoid_evaluations"),
                real("trapezoid_error", 6, Column::scientific), integer("monte_carlo_evaluations"),
                real("monte_carlo_rmse", 6, Column::scientific)}};
  std::vector<SlopeLine> lines;  // one per row of slopes
  double seconds = 0.0;
};

// Per study and method, in the plan's order: a row per n or N, then the fitted slope.
Results tabulate(const Plan& plan, const std::vector<Estimate>& estimates, double seconds) {
  Results r;
  r.seconds = seconds;
  for (std::size_t s = 0; s < plan.studies.size(); ++s) {
    const Study& study = plan.studies[s];
    const double exact = reference(study);
    std::vector<Cell> at_budget{study.name(), study.dims, exact};  // each method's last row
    for (bool trapezoid : {true, false}) {
      const char* method = trapezoid ? "trapezoid" : "monte_carlo";
      std::vector<double> n, error;
      for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
        const Task& t = plan.tasks[i];
        if (t.study != s || t.trapezoid != trapezoid) continue;
        const double value = estimates[i].value, rmse = estimates[i].rmse;
        r.errors.add_row({study.name(), study.dims, method, trapezoid ? Cell{t.n} : Cell{},
                          trapezoid ? t.evaluations : t.n, value, exact, std::abs(value - exact),
                          trapezoid ? Cell{} : Cell{rmse}});
        n.push_back(static_cast<double>(trapezoid ? t.evaluations : t.n));
        error.push_back(trapezoid ? std::abs(value - exact) : rmse);
      }
      if (trapezoid) at_budget.push_back(r.errors.at(r.errors.size() - 1, "points_per_axis"));
      at_budget.push_back(static_cast<std::uint64_t>(n.back()));
      at_budget.push_back(error.back());
      const double theory = study.theory_slope(trapezoid);
      const ErrorSlope slope = fit_error_slope(n, error, theory);
      r.slopes.add_row({study.name(), study.dims, method, slope.fit.slope,
                        slope.fit.slope_standard_error, theory, slope.points});
      r.lines.push_back({slope.fit.slope, theory, slope.guide_constant});
    }
    if (study.kind == Kind::gaussian_kd || study.kind == Kind::unit_ball_kd)
      r.budget.add_row(at_budget);
  }
  return r;
}

void run(const CLI::App& app, const Options& o) {
  // No images: the program, its threads and its tables (a failed allocation still says why).
  check_memory_limit(images_in_memory(0.0, 0.0, o.common.threads, "the program and its threads"),
                     "--threads", "lower it");
  const Plan plan = make_plan(o.dims, o.max_evaluations, o.trials);
  // Every task (a grid n, or N with its trials) on any core, largest first; each writes
  // only its own estimate, so the numbers do not depend on --threads.
  const Stopwatch clock;
  std::vector<Estimate> estimates(plan.tasks.size());
  ProgressBar progress("ch03 integrating", static_cast<std::uint64_t>(plan.total_evaluations),
                       o.common.quiet);
  parallel_for(plan.schedule.size(), o.common.threads, [&](std::size_t j) {
    const Task& task = plan.tasks[plan.schedule[j]];
    estimates[plan.schedule[j]] = estimate(plan.studies[task.study], task, o, progress);
  });
  progress.finish();
  const Results r = tabulate(plan, estimates, clock.seconds());

  write_csv(o.common.dir / "errors.csv", r.errors);
  write_csv(o.common.dir / "slopes.csv", r.slopes);
  write_csv(o.common.dir / "budget.csv", r.budget);
  write_plots(o, plan, r);
  write_json(o.common.dir / "summary.json", summary_of(k_chapter, app, o, plan, r));
  write_timings(o.common.dir, timings_of(k_chapter, o, plan, r), run_flags_json(app));
  if (!o.common.quiet) print_report(k_chapter, o, plan, r);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_number_option(app, "--trials", o.trials, "Monte Carlo runs per N (the rmse is over these)", 1,
                    100000);
  add_number_option(app, "--max-evaluations", o.max_evaluations,
                    "Function evaluations at the largest point of every study", std::uint64_t{1},
                    k_max_budget);
  add_list_option(app, "--dims", o.dims,
                  "Dimensions k of the k-dimensional integrands, e.g. 1,2,4,8 (the ball at "
                  "k >= 2, and always at k = 2)",
                  1, k_max_dims);
  return app.run(argc, argv, [&] { run(app, o); });
}
