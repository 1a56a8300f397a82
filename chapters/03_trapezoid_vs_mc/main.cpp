// Chapter 03: the trapezoid rule against Monte Carlo, in one dimension and in k.
//
//   I   = integral of f over the domain (known here in closed form)
//   T   = sum over a grid of n points per axis of w_1...w_k f(x)     N = n^k evaluations
//         error O(n^-2) = O(N^(-2/k)) for smooth f, O(n^-1) = O(N^(-1/k)) where f jumps
//   F_N = vol/N sum_i f(X_i), X_i uniform                          N evaluations
//         unbiased, rms error sqrt(V[F_N]) = O(N^(-1/2)) in every dimension
//   for each integrand, method and k: the error against N on a log grid, and the slope of
//   log(error) against log(N), beside the slope theory predicts.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "integration/integrands.hpp"
#include "integration/log_grid.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/quadrature.hpp"
#include "integration/statistics.hpp"
#include "io/cli.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "io/summary.hpp"

using namespace mcrt;

namespace {

struct Options {
  CommonOptions common;
  int trials = 16;                          // Monte Carlo runs per N: rmse over these
  std::uint64_t max_evaluations = 1 << 20;  // N of the largest point of every study
  std::vector<int> dims = {1, 2, 3, 4, 5, 6, 7, 8};  // the k of the k-dimensional integrands
};

constexpr int k_max_dims = 12;                     // 3^12 = 531441 evaluations at least
constexpr int k_disk_dims = 2;                     // the lecture's disk, always studied
constexpr std::uint64_t k_max_budget = 1'000'000'000;
constexpr double k_max_total_evaluations = 2e11;   // about 20 minutes on 2 cores
constexpr int k_per_decade = 5;                    // grid points per factor of 10 in N or n
constexpr std::uint64_t k_first_monte_carlo_n = 10;

// ---- the integrands of the study ---------------------------------------------------------

enum class Kind { gaussian_1d, ceil_sin_1d, gaussian_kd, unit_ball_kd };

struct Study {
  Kind kind;
  int dims;
  const char* name() const {
    switch (kind) {
      case Kind::gaussian_1d: return "gaussian_1d";
      case Kind::ceil_sin_1d: return "ceil_sin_1d";
      case Kind::gaussian_kd: return "gaussian_kd";
      case Kind::unit_ball_kd: return "unit_ball_kd";
    }
    return "";
  }
  bool smooth() const { return kind == Kind::gaussian_1d || kind == Kind::gaussian_kd; }
};

// Calls visit(f, domain) with the study's integrand as its own type, so every loop over
// samples is compiled for one integrand and inlined.
template <class Visit>
auto with_integrand(const Study& study, Visit&& visit) {
  switch (study.kind) {
    case Kind::gaussian_1d: { const Gaussian1D f; return visit(f, f.domain); }
    case Kind::ceil_sin_1d: { const CeilSinSquare1D f; return visit(f, f.domain); }
    case Kind::gaussian_kd: { const GaussianProduct f{study.dims}; return visit(f, f.domain()); }
    case Kind::unit_ball_kd:
    default: { const UnitBallIndicator f{study.dims}; return visit(f, f.domain()); }
  }
}

double reference(const Study& study) {
  return with_integrand(study, [](const auto& f, const auto&) { return f.reference(); });
}

// The slope of log(error) against log(N) that the simple statement predicts.
double theory_slope(const Study& study, bool trapezoid) {
  if (!trapezoid) return -0.5;
  return (study.smooth() ? -2.0 : -1.0) / study.dims;
}

// ---- the work: one task per trapezoid grid and per Monte Carlo N -------------------------

struct Task {
  std::size_t study;
  std::size_t grid_index;  // which N (Monte Carlo) or n (trapezoid) of the study
  bool trapezoid;
  std::uint64_t n;         // points per axis (trapezoid) or samples per trial (Monte Carlo)
  std::uint64_t evaluations;  // n^k, or trials * N
};

// What a task finds: T, or the mean of F_N over the trials and their rms error.
struct TaskResult {
  double estimate = 0.0;
  double rmse = 0.0;
};

// T with n points per axis.
double run_trapezoid(const Study& study, std::uint64_t n) {
  return with_integrand(study, [n](const auto& f, const auto& domain) {
    return trapezoid(f, domain, n);
  });
}

// `trials` independent F_N, trial t from generator stream (study, N index, t) of the seed:
// the same numbers whatever the thread count. Their mean, and rmse = sqrt(mean (F_N - I)^2).
TaskResult run_monte_carlo(const Study& study, const Task& task, int trials, std::uint64_t seed) {
  return with_integrand(study, [&](const auto& f, const auto& domain) {
    ErrorStats errors(f.reference());
    for (int t = 0; t < trials; ++t) {
      const std::uint64_t stream = stream_index(task.study * 1000 + task.grid_index,
                                                static_cast<std::uint64_t>(t));
      Rng rng(seed, stream);
      errors.add(monte_carlo(f, domain, task.n, rng).estimate);
    }
    return TaskResult{errors.mean(), errors.rmse()};
  });
}

// ---- the study's plan, checked before any work ------------------------------------------

struct Plan {
  std::vector<Study> studies;
  std::vector<std::vector<std::uint64_t>> points_per_axis;  // trapezoid n, per study
  std::vector<std::uint64_t> samples;                        // Monte Carlo N, all studies
  std::vector<Task> tasks;              // per study: its grids n, then its Monte Carlo N
  std::vector<std::size_t> schedule;    // task indices, largest first
  double total_evaluations = 0.0;
};

// The k of --dims, sorted, each once.
std::vector<int> sorted_dims(const Options& o) {
  std::vector<int> dims = o.dims;
  std::sort(dims.begin(), dims.end());
  dims.erase(std::unique(dims.begin(), dims.end()), dims.end());
  return dims;
}

Plan make_plan(const Options& o) {
  const std::vector<int> dims = sorted_dims(o);
  // A slope needs two grid sizes, n = 2 and 3 points per axis, at the largest k.
  const int largest = std::max(dims.back(), k_disk_dims);
  const std::uint64_t smallest_grid = grid_evaluations(3, largest);
  if (smallest_grid > o.max_evaluations)
    throw UsageError("--max-evaluations " + std::to_string(o.max_evaluations) +
                     " is below the smallest trapezoid study at --dims " +
                     std::to_string(largest) + ": n = 2 and 3 points per axis need 3^" +
                     std::to_string(largest) + " = " + std::to_string(smallest_grid) +
                     " evaluations; raise --max-evaluations or lower --dims");
  Plan plan;
  plan.studies = {{Kind::gaussian_1d, 1}, {Kind::ceil_sin_1d, 1}};
  for (int k : dims) plan.studies.push_back({Kind::gaussian_kd, k});
  // The ball at every k >= 2 of --dims, and always at k = 2: the disk. (At k = 1 it would
  // be the whole interval [-1, 1], nothing to study.)
  if (!std::binary_search(dims.begin(), dims.end(), k_disk_dims))
    plan.studies.push_back({Kind::unit_ball_kd, k_disk_dims});
  for (int k : dims)
    if (k >= 2) plan.studies.push_back({Kind::unit_ball_kd, k});
  plan.samples = log_grid(std::min(k_first_monte_carlo_n, o.max_evaluations), o.max_evaluations,
                          k_per_decade);
  for (const Study& study : plan.studies)
    plan.points_per_axis.push_back(
        log_grid(2, points_per_axis_within(o.max_evaluations, study.dims), k_per_decade));

  // The whole study's cost, refused before any work if it is far too much.
  double monte_carlo_samples = 0.0;
  for (std::uint64_t n : plan.samples) monte_carlo_samples += static_cast<double>(n);
  for (std::size_t s = 0; s < plan.studies.size(); ++s) {
    plan.total_evaluations += o.trials * monte_carlo_samples;
    for (std::uint64_t n : plan.points_per_axis[s])
      plan.total_evaluations += static_cast<double>(grid_evaluations(n, plan.studies[s].dims));
  }
  if (plan.total_evaluations > k_max_total_evaluations) {
    char message[300];
    std::snprintf(message, sizeof message,
                  "--trials %d with --max-evaluations %llu and %zu --dims: %.3g evaluations in "
                  "all, above the limit of %.3g; lower one of them",
                  o.trials, static_cast<unsigned long long>(o.max_evaluations), dims.size(),
                  plan.total_evaluations, k_max_total_evaluations);
    throw UsageError(message);
  }

  for (std::size_t s = 0; s < plan.studies.size(); ++s) {
    const int k = plan.studies[s].dims;
    for (std::size_t i = 0; i < plan.points_per_axis[s].size(); ++i) {
      const std::uint64_t n = plan.points_per_axis[s][i];
      plan.tasks.push_back({s, i, true, n, grid_evaluations(n, k)});
    }
    for (std::size_t i = 0; i < plan.samples.size(); ++i)
      plan.tasks.push_back({s, i, false, plan.samples[i], o.trials * plan.samples[i]});
  }
  // Largest tasks first, so the cores finish together.
  plan.schedule.resize(plan.tasks.size());
  for (std::size_t i = 0; i < plan.tasks.size(); ++i) plan.schedule[i] = i;
  std::stable_sort(plan.schedule.begin(), plan.schedule.end(), [&](std::size_t a, std::size_t b) {
    return plan.tasks[a].evaluations > plan.tasks[b].evaluations;
  });
  return plan;
}

// ---- results ----------------------------------------------------------------------------

struct ErrorRow {
  std::size_t study;
  bool trapezoid;
  std::uint64_t points_per_axis;  // trapezoid only
  std::uint64_t evaluations;
  double estimate;  // T, or the mean of F_N over the trials
  double reference;
  double abs_error;  // |estimate - reference|
  double rmse;       // Monte Carlo only: sqrt(mean over trials of (F_N - I)^2)
};

struct SlopeRow {
  std::size_t study;
  bool trapezoid;
  LineFit fit;
  double theory;
  int points;  // rows in the fit (zero errors cannot be fitted in log space)
  // A line of the theory's slope through the centre of the data, for the plots: c N^theory.
  double theory_line_constant;
};

SlopeRow fit_slope(const std::vector<ErrorRow>& rows, std::size_t study, bool trapezoid,
                   double theory) {
  std::vector<double> n, error;
  for (const ErrorRow& row : rows) {
    const double e = trapezoid ? row.abs_error : row.rmse;
    if (row.study == study && row.trapezoid == trapezoid && e > 0.0) {
      n.push_back(static_cast<double>(row.evaluations));
      error.push_back(e);
    }
  }
  SlopeRow slope{study, trapezoid, {}, theory, static_cast<int>(n.size()), 0.0};
  if (n.size() >= 2) slope.fit = fit_log_log(n, error);
  double mean_log_n = 0.0, mean_log_error = 0.0;
  for (std::size_t i = 0; i < n.size(); ++i) {
    mean_log_n += std::log(n[i]) / static_cast<double>(n.size());
    mean_log_error += std::log(error[i]) / static_cast<double>(n.size());
  }
  slope.theory_line_constant = std::exp(mean_log_error - theory * mean_log_n);
  return slope;
}

const char* method_name(bool trapezoid) { return trapezoid ? "trapezoid" : "monte_carlo"; }

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string errors_csv(const std::vector<Study>& studies, const std::vector<ErrorRow>& rows) {
  std::string csv = "integrand,dims,method,points_per_axis,evaluations,estimate,reference,"
                    "abs_error,rmse\n";
  for (const ErrorRow& r : rows) {
    csv += std::string(studies[r.study].name()) + "," + std::to_string(studies[r.study].dims) +
           "," + method_name(r.trapezoid) + "," +
           (r.trapezoid ? std::to_string(r.points_per_axis) : "") + "," +
           std::to_string(r.evaluations) + "," + format("%.17g", r.estimate) + "," +
           format("%.17g", r.reference) + "," + format("%.6e", r.abs_error) + "," +
           (r.trapezoid ? "" : format("%.6e", r.rmse)) + "\n";
  }
  return csv;
}

std::string slopes_csv(const std::vector<Study>& studies, const std::vector<SlopeRow>& slopes) {
  std::string csv = "integrand,dims,method,fitted_slope,standard_error,theory_slope,points\n";
  for (const SlopeRow& s : slopes)
    csv += std::string(studies[s.study].name()) + "," + std::to_string(studies[s.study].dims) +
           "," + method_name(s.trapezoid) + "," + format("%.6f", s.fit.slope) + "," +
           format("%.6f", s.fit.slope_standard_error) + "," + format("%.6f", s.theory) + "," +
           std::to_string(s.points) + "\n";
  return csv;
}

// ---- plots --------------------------------------------------------------------------------

// Error against N for one integrand: the trapezoid's |T - I|, Monte Carlo's rmse, and a line
// of each method's theoretical slope through the centre of its data.
Plot error_plot(const std::string& name, const std::string& title, const Study& study,
                const SlopeRow& trapezoid_slope, const SlopeRow& mc_slope,
                const std::string& trapezoid_theory_label) {
  const std::string select = "strcol(1) eq '" + std::string(study.name()) +
                             "' && $2 == " + std::to_string(study.dims) + " && strcol(3) eq ";
  Plot plot;
  plot.name = name;
  plot.title = title;
  plot.x_label = "function evaluations N";
  plot.y_label = "error";
  plot.log_x = plot.log_y = true;
  plot.settings = "set key bottom left\nset style data linespoints\n"
                  "c_trap = " + format("%.17g", trapezoid_slope.theory_line_constant) + "\n"
                  "c_mc = " + format("%.17g", mc_slope.theory_line_constant) + "\n";
  plot.plot = "plot 'errors.csv' every ::1 using 5:(" + select + "'trapezoid' ? $8 : 1/0) "
              "pt 7 lc rgb '#1f77b4' title 'trapezoid |T - I| (slope " +
              format("%.2f", trapezoid_slope.fit.slope) + ")', \\\n"
              "  '' every ::1 using 5:(" + select + "'monte_carlo' ? $9 : 1/0) pt 5 "
              "lc rgb '#d62728' title 'Monte Carlo rmse (slope " +
              format("%.2f", mc_slope.fit.slope) + ")', \\\n"
              "  c_trap * x**(" + format("%.6g", trapezoid_slope.theory) + ") with lines dt 2 "
              "lc rgb '#1f77b4' title '" + trapezoid_theory_label + "', \\\n"
              "  c_mc * x**(-0.5) with lines dt 2 lc rgb '#d62728' title 'N^{-1/2}'";
  return plot;
}

// Fitted slope against k for both k-dimensional integrands and both methods, with the
// theory: -2/k and -1/k for the trapezoid rule, -1/2 for Monte Carlo.
Plot slopes_plot(int largest_dims) {
  const auto series = [](const std::string& integrand, const std::string& method) {
    return "every ::1 using 2:(strcol(1) eq '" + integrand + "' && strcol(3) eq '" + method +
           "' ? $4 : 1/0):5 with yerrorlines";
  };
  Plot plot;
  plot.name = "slopes_vs_k";
  plot.title = "Fitted slope of log(error) against log(N), by dimension k";
  plot.x_label = "dimension k";
  plot.y_label = "slope";
  plot.settings = "set key bottom right\nset xrange [0.5:" + std::to_string(largest_dims) +
                  ".5]\nset yrange [-2.2:0.3]\nset xtics 1\nset samples 400\n";
  plot.plot = "plot 'slopes.csv' " + series("gaussian_kd", "trapezoid") +
              " pt 7 lc rgb '#1f77b4' title 'trapezoid, smooth (e^{-|x|^2})', \\\n"
              "  '' " + series("unit_ball_kd", "trapezoid") +
              " pt 9 lc rgb '#2ca02c' title 'trapezoid, ball indicator', \\\n"
              "  '' " + series("gaussian_kd", "monte_carlo") +
              " pt 5 lc rgb '#d62728' title 'Monte Carlo, smooth', \\\n"
              "  '' " + series("unit_ball_kd", "monte_carlo") +
              " pt 11 lc rgb '#ff7f0e' title 'Monte Carlo, ball indicator', \\\n"
              "  -2.0/x with lines dt 2 lc rgb '#1f77b4' title 'theory -2/k (smooth)', \\\n"
              "  -1.0/x with lines dt 2 lc rgb '#2ca02c' title 'theory -1/k (jump)', \\\n"
              "  -0.5 with lines dt 2 lc rgb '#d62728' title 'theory -1/2 (Monte Carlo)'";
  return plot;
}

// ---- the chapter ------------------------------------------------------------------------

int run(const CLI::App& app, const Options& o) {
  const Plan plan = make_plan(o);
  prepare_output_dir(o.common.out);

  // Every task writes only its own result: the same numbers on any number of threads.
  const auto start = std::chrono::steady_clock::now();
  std::vector<TaskResult> results(plan.tasks.size());
  ProgressBar progress("ch03 integrating", static_cast<std::uint64_t>(plan.total_evaluations),
                       o.common.quiet);
  parallel_for(plan.schedule.size(), o.common.threads, [&](std::size_t j) {
    const std::size_t i = plan.schedule[j];
    const Task& task = plan.tasks[i];
    const Study& study = plan.studies[task.study];
    results[i] = task.trapezoid ? TaskResult{run_trapezoid(study, task.n), 0.0}
                                : run_monte_carlo(study, task, o.trials, o.common.seed);
    progress.advance(task.evaluations);
  });
  progress.finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The rows, in the plan's order: per study its trapezoid grids, then each Monte Carlo N.
  std::vector<ErrorRow> rows;
  for (std::size_t i = 0; i < plan.tasks.size(); ++i) {
    const Task& task = plan.tasks[i];
    const double exact = reference(plan.studies[task.study]);
    rows.push_back({task.study, task.trapezoid, task.trapezoid ? task.n : 0,
                    task.trapezoid ? task.evaluations : task.n, results[i].estimate, exact,
                    std::abs(results[i].estimate - exact), results[i].rmse});
  }
  std::vector<SlopeRow> slopes;
  for (std::size_t s = 0; s < plan.studies.size(); ++s)
    for (bool trapezoid : {true, false})
      slopes.push_back(fit_slope(rows, s, trapezoid, theory_slope(plan.studies[s], trapezoid)));

  write_file_atomic(o.common.out / "errors.csv", errors_csv(plan.studies, rows));
  write_file_atomic(o.common.out / "slopes.csv", slopes_csv(plan.studies, slopes));
  // Studies 0 and 1 are the 1D integrands; the disk is the unit ball at k = 2.
  const std::vector<int> dims = sorted_dims(o);
  std::size_t disk = 0;
  for (std::size_t s = 0; s < plan.studies.size(); ++s)
    if (plan.studies[s].kind == Kind::unit_ball_kd && plan.studies[s].dims == k_disk_dims)
      disk = s;
  write_plot(o.common.out, error_plot("smooth_1d", "e^{-x^2} on [0,1]: error against N",
                                      plan.studies[0], slopes[0], slopes[1], "N^{-2}"));
  write_plot(o.common.out,
             error_plot("discontinuous_1d", "ceil(sin x^2) on [0,3]: error against N",
                        plan.studies[1], slopes[2], slopes[3], "N^{-1}"));
  write_plot(o.common.out,
             error_plot("disk_2d", "Unit disk in [-1,1]^2: error against N", plan.studies[disk],
                        slopes[2 * disk], slopes[2 * disk + 1], "N^{-1/2} (n^{-1})"));
  write_plot(o.common.out, slopes_plot(std::max(dims.back(), k_disk_dims)));

  Json summary;
  summary["chapter"] = "ch03_trapezoid_vs_mc";
  summary["seed"] = o.common.seed;
  summary["threads"] = o.common.threads;
  summary["trials"] = o.trials;
  summary["max_evaluations"] = o.max_evaluations;
  summary["dims"] = dims;
  summary["evaluations"] = plan.total_evaluations;
  summary["seconds"] = seconds;
  summary["evaluations_per_second"] = seconds > 0.0 ? plan.total_evaluations / seconds : 0.0;
  Json references = Json::object();
  for (const Study& study : plan.studies)
    references[std::string(study.name()) + "_" + std::to_string(study.dims)] = reference(study);
  summary["references"] = references;
  Json slope_list = Json::array();
  for (const SlopeRow& s : slopes)
    slope_list.push_back({{"integrand", plan.studies[s.study].name()},
                          {"dims", plan.studies[s.study].dims},
                          {"method", method_name(s.trapezoid)},
                          {"fitted_slope", s.fit.slope},
                          {"standard_error", s.fit.slope_standard_error},
                          {"theory_slope", s.theory},
                          {"points", s.points}});
  summary["slopes"] = slope_list;
  summary["flags"] = flags_json(app);
  write_json(o.common.out / "summary.json", summary);

  if (!o.common.quiet) {
    std::string k_list;
    for (int k : dims) k_list += (k_list.empty() ? "" : ",") + std::to_string(k);
    std::printf("ch03_trapezoid_vs_mc  N up to %llu  %d trials  k = %s  %d threads\n",
                static_cast<unsigned long long>(o.max_evaluations), o.trials, k_list.c_str(),
                o.common.threads);
    std::printf("  %-13s %4s  %-12s %16s  %8s\n", "integrand", "k", "method", "fitted slope",
                "theory");
    for (const SlopeRow& s : slopes)
      std::printf("  %-13s %4d  %-12s %8.3f +- %5.3f  %8.3f\n", plan.studies[s.study].name(),
                  plan.studies[s.study].dims, method_name(s.trapezoid), s.fit.slope,
                  s.fit.slope_standard_error, s.theory);
    std::printf("  %.3g evaluations in %.2f s (%.3g per second)\n", plan.total_evaluations,
                seconds, seconds > 0.0 ? plan.total_evaluations / seconds : 0.0);
    std::printf("  wrote %s/{errors.csv,slopes.csv,summary.json} and plots\n",
                o.common.out.string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Chapter 03: the trapezoid rule against Monte Carlo. Error against the number "
               "of function evaluations N for smooth and discontinuous integrands in 1 and k "
               "dimensions, and the fitted convergence slopes.",
               "ch03_trapezoid_vs_mc"};
  Options o;
  add_common_options(app, o.common, Chapter{"ch03_trapezoid_vs_mc", ""});
  app.add_option("--trials", o.trials, "Monte Carlo runs per N (the rmse is over these)")
      ->check(CLI::Range(1, 100000));
  app.add_option("--max-evaluations", o.max_evaluations,
                 "Function evaluations at the largest point of every study")
      ->check(CLI::Range(std::uint64_t{1}, k_max_budget));
  app.add_option("--dims", o.dims,
                 "Dimensions k of the k-dimensional integrands, e.g. 1,2,4,8 (the ball at "
                 "k >= 2, and always at k = 2)")
      ->delimiter(',')
      ->check(CLI::Range(1, k_max_dims));
  return run_chapter(app, argc, argv, [&] { return run(app, o); });
}
