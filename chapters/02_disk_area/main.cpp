// Chapter 02: the area of the unit disk by Monte Carlo, the lecture's first randomized
// algorithm.
//
//   M = 0
//   repeat N times:
//     pick (x, y) uniformly in [-1, 1]^2
//     if x^2 + y^2 <= 1: M = M + 1
//   area = 4 M / N
//
// Each point lands in the disk with probability p = pi/4, so M ~ Binomial(N, p),
// E[4M/N] = pi and V[4M/N] = 16 p (1 - p) / N: the error falls as N^-1/2. In k dimensions
// 2^k M / N estimates the ball's volume V_k with the same rate and a constant that grows
// quickly with k. The estimators live in common/disk_area.hpp; this program measures them.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "integration/ball.hpp"
#include "integration/disk_area.hpp"
#include "integration/log_grid.hpp"
#include "integration/statistics.hpp"
#include "io/cli.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "io/summary.hpp"

using namespace mcrt;

namespace {

struct Options {
  CommonOptions common;
  std::uint64_t max_n = 10'000'000;  // largest N of the 2D error study (from N = 10)
  int trials = 100;                  // independent estimates per N
  std::vector<int> dims = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};  // k of the ball table
  std::uint64_t ball_n = 100'000;    // N of the ball table; largest N of the ball error study
  int points = 2000;                 // points drawn in the picture
};

constexpr int k_per_decade = 4;               // sizes per factor of 10 on the N grids
constexpr int k_error_study_dims[] = {2, 5, 10};  // the k of ball_error_vs_n
// Limits on the work: ~10 minutes on 2 cores at the speeds this chapter measures.
constexpr double k_max_disk_points = 1e12;
constexpr double k_max_ball_coordinates = 1e11;

// Every estimate has its own random stream, chosen by (part, index, trial), never by thread:
// the output does not depend on --threads.
enum class Part : std::uint64_t { disk_error = 0, ball_table = 1, ball_error = 2, picture = 3 };

std::uint64_t stream_for(Part part, std::uint64_t index, std::uint64_t trial) {
  return stream_index((static_cast<std::uint64_t>(part) << 24) | index, trial);
}

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// ---- repeated estimates ------------------------------------------------------------------

// One row of an error study: `trials` independent estimates at one N against the exact value.
struct ErrorRow {
  std::uint64_t n = 0;
  int trials = 0;
  double mean_estimate = 0.0;
  double bias = 0.0;           // mean_estimate - exact
  double empirical_std = 0.0;  // sample standard deviation of the estimates
  double theory_std = 0.0;     // |box| sqrt(p (1 - p) / N)
  double rmse = 0.0;           // sqrt(mean (estimate - exact)^2)
};

// `trials` estimates at one N, in parallel over trials; estimate t uses stream_of(t).
template <class Estimate, class StreamOf>
ErrorRow run_trials(std::uint64_t n, int trials, double exact, double theory_std,
                    const Options& o, ProgressBar& progress, Estimate&& estimate,
                    StreamOf&& stream_of) {
  std::vector<double> estimates(static_cast<std::size_t>(trials));
  parallel_for(estimates.size(), o.common.threads, [&](std::size_t t) {
    Rng rng(o.common.seed, stream_of(t));
    estimates[t] = estimate(n, rng);
    progress.advance(n);
  });
  ErrorStats errors(exact);
  for (double f : estimates) errors.add(f);
  return {n, trials, errors.mean(), errors.bias(), errors.stddev(), theory_std, errors.rmse()};
}

LineFit error_slope(std::span<const ErrorRow> rows) {
  std::vector<double> n, rmse;
  for (const ErrorRow& row : rows) {
    n.push_back(static_cast<double>(row.n));
    rmse.push_back(row.rmse);
  }
  return fit_log_log(n, rmse);
}

// ---- the three studies -------------------------------------------------------------------

// 1. Error against N in 2D: trials x (4 M / N) at every N of the grid.
std::vector<ErrorRow> disk_error_study(const std::vector<std::uint64_t>& grid, const Options& o,
                                       ProgressBar& progress) {
  std::vector<ErrorRow> rows;
  for (std::size_t i = 0; i < grid.size(); ++i)
    rows.push_back(run_trials(grid[i], o.trials, k_pi, disk_area_theory_std(grid[i]), o,
                              progress, estimate_disk_area, [&](std::size_t t) {
                                return stream_for(Part::disk_error, i, t);
                              }));
  return rows;
}

// 3. The k-ball: trials x (2^k M / N) at one N for each k of --dims.
std::vector<ErrorRow> ball_table(const Options& o, ProgressBar& progress) {
  std::vector<ErrorRow> rows;
  for (int k : o.dims)
    rows.push_back(run_trials(
        o.ball_n, o.trials, unit_ball_volume(k), ball_volume_theory_std(k, o.ball_n), o,
        progress, [k](std::uint64_t n, Rng& rng) { return estimate_ball_volume(k, n, rng); },
        [&](std::size_t t) { return stream_for(Part::ball_table, k, t); }));
  return rows;
}

// 3b. rmse against N for the k of k_error_study_dims, rows k by k.
std::vector<std::vector<ErrorRow>> ball_error_study(const std::vector<std::uint64_t>& grid,
                                                    const Options& o, ProgressBar& progress) {
  std::vector<std::vector<ErrorRow>> studies;
  for (int k : k_error_study_dims) {
    std::vector<ErrorRow>& rows = studies.emplace_back();
    for (std::size_t i = 0; i < grid.size(); ++i)
      rows.push_back(run_trials(
          grid[i], o.trials, unit_ball_volume(k), ball_volume_theory_std(k, grid[i]), o,
          progress, [k](std::uint64_t n, Rng& rng) { return estimate_ball_volume(k, n, rng); },
          [&](std::size_t t) { return stream_for(Part::ball_error, 256 * k + i, t); }));
  }
  return studies;
}

// 2. The picture: --points points, inside or not, and their estimate 4 M / N.
struct Picture {
  std::string csv = "x,y,inside\n";
  double estimate = 0.0;
};

Picture draw_points(const Options& o) {
  Picture picture;
  Rng rng(o.common.seed, stream_for(Part::picture, 0, 0));
  std::uint64_t inside = 0;
  for (int i = 0; i < o.points; ++i) {
    const double point[2] = {2.0 * rng.uniform() - 1.0, 2.0 * rng.uniform() - 1.0};
    const bool in = inside_unit_ball(point);
    inside += in;
    picture.csv += format("%.6f", point[0]) + "," + format("%.6f", point[1]) + "," +
                   (in ? "1" : "0") + "\n";
  }
  picture.estimate = 4.0 * static_cast<double>(inside) / o.points;
  return picture;
}

// ---- outputs -----------------------------------------------------------------------------

std::string error_row_csv(const ErrorRow& row) {
  return std::to_string(row.n) + "," + std::to_string(row.trials) + "," +
         format("%.10g", row.mean_estimate) + "," + format("%.10g", row.bias) + "," +
         format("%.10g", row.empirical_std) + "," + format("%.10g", row.theory_std) + "," +
         format("%.10g", row.rmse) + "\n";
}

std::string disk_csv(std::span<const ErrorRow> rows) {
  std::string csv = "n,trials,mean_estimate,bias,empirical_std,theory_std,rmse\n";
  for (const ErrorRow& row : rows) csv += error_row_csv(row);
  return csv;
}

std::string ball_csv(const Options& o, std::span<const ErrorRow> rows) {
  std::string csv = "k,n,trials,exact_volume,mean_estimate,empirical_std,theory_std,relative_std\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ErrorRow& row = rows[i];
    const double exact = unit_ball_volume(o.dims[i]);
    csv += std::to_string(o.dims[i]) + "," + std::to_string(row.n) + "," +
           std::to_string(row.trials) + "," + format("%.10g", exact) + "," +
           format("%.10g", row.mean_estimate) + "," + format("%.10g", row.empirical_std) + "," +
           format("%.10g", row.theory_std) + "," + format("%.10g", row.theory_std / exact) + "\n";
  }
  return csv;
}

std::string ball_error_csv(const std::vector<std::vector<ErrorRow>>& studies) {
  std::string csv = "k,n,trials,mean_estimate,empirical_std,theory_std,rmse\n";
  for (std::size_t s = 0; s < studies.size(); ++s)
    for (const ErrorRow& row : studies[s])
      csv += std::to_string(k_error_study_dims[s]) + "," + std::to_string(row.n) + "," +
             std::to_string(row.trials) + "," + format("%.10g", row.mean_estimate) + "," +
             format("%.10g", row.empirical_std) + "," + format("%.10g", row.theory_std) + "," +
             format("%.10g", row.rmse) + "\n";
  return csv;
}

// rmse with error bars +- rmse / sqrt(2 T) (the standard error of a root mean square of T
// near-normal squared errors), the theory line, and a slope -1/2 guide above it.
Plot error_plot(const LineFit& fit) {
  Plot plot;
  plot.name = "error_vs_n";
  plot.title = "Disk area 4M/N: rms error against N (fitted slope " + format("%.3f", fit.slope) +
               ", theory -1/2)";
  plot.x_label = "points N";
  plot.y_label = "rms error of 4M/N";
  plot.log_x = plot.log_y = true;
  plot.settings = "set key bottom left\nguide(n) = " + format("%.6g", 4.0 * disk_area_theory_std(1)) +
                  " / sqrt(n)\n";
  plot.plot =
      "plot 'disk_area.csv' every ::1 using 1:7:($7 / sqrt(2 * $2)) with yerrorbars pt 7 "
      "lc rgb '#1f77b4' title 'rmse over the trials', \\\n"
      "  '' every ::1 using 1:6 with lines lw 2 lc rgb '#d62728' "
      "title 'theory 4 sqrt(p(1-p)/N)', \\\n"
      "  '' every ::1 using 1:(guide($1)) with lines dt 2 lc rgb '#555555' title 'slope -1/2'";
  return plot;
}

Plot picture_plot(const Options& o, double estimate) {
  Plot plot;
  plot.name = "points";
  plot.title = std::to_string(o.points) + " points: 4M/N = " + format("%.4f", estimate) +
               "  (pi = 3.1416)";
  plot.x_label = "x";
  plot.y_label = "y";
  plot.width = plot.height = 700;
  plot.settings =
      "set size ratio -1\nset xrange [-1:1]\nset yrange [-1:1]\nset key outside top center horizontal\n"
      "set object 1 circle at 0,0 size 1 front fillstyle empty border lc rgb 'black' lw 2\n";
  plot.plot =
      "plot 'points.csv' every ::1 using 1:($3 > 0 ? $2 : 1/0) with points pt 7 ps 0.4 "
      "lc rgb '#1f77b4' title 'inside', \\\n"
      "  '' every ::1 using 1:($3 > 0 ? 1/0 : $2) with points pt 7 ps 0.4 lc rgb '#ff7f0e' "
      "title 'outside'";
  return plot;
}

Plot ball_error_plot() {
  Plot plot;
  plot.name = "ball_error_vs_n";
  plot.title = "k-ball volume 2^k M/N: rms error against N";
  plot.x_label = "points N";
  plot.y_label = "rms error of 2^k M/N";
  plot.log_x = plot.log_y = true;
  plot.settings = "set key bottom left\n";
  const char* colours[] = {"#1f77b4", "#2ca02c", "#d62728"};
  plot.plot = "plot ";
  for (int s = 0; s < 3; ++s) {
    const std::string k = std::to_string(k_error_study_dims[s]);
    plot.plot += std::string(s ? ", \\\n  " : "") + "'ball_error_vs_n.csv' every ::1 using 2:($1 == " +
                 k + " ? $7 : 1/0) with points pt 7 lc rgb '" + colours[s] + "' title 'k = " + k +
                 " rmse', \\\n  '' every ::1 using 2:($1 == " + k +
                 " ? $6 : 1/0) with lines lc rgb '" + colours[s] + "' title 'k = " + k + " theory'";
  }
  return plot;
}

// ---- the chapter -------------------------------------------------------------------------

double grid_sum(const std::vector<std::uint64_t>& grid) {
  return std::accumulate(grid.begin(), grid.end(), 0.0,
                         [](double sum, std::uint64_t n) { return sum + static_cast<double>(n); });
}

int run(const CLI::App& app, const Options& o) {
  const std::vector<std::uint64_t> disk_grid = log_grid(10, o.max_n, k_per_decade);
  const std::vector<std::uint64_t> ball_grid = log_grid(10, o.ball_n, k_per_decade);
  // The work, checked before any is done: points of the disk study, coordinates of the balls.
  const double disk_points = o.trials * grid_sum(disk_grid);
  double ball_points = 0.0, ball_coordinates = 0.0;
  for (int k : o.dims) {
    ball_points += static_cast<double>(o.trials) * static_cast<double>(o.ball_n);
    ball_coordinates += static_cast<double>(o.trials) * static_cast<double>(o.ball_n) * k;
  }
  for (int k : k_error_study_dims) {
    ball_points += o.trials * grid_sum(ball_grid);
    ball_coordinates += o.trials * grid_sum(ball_grid) * k;
  }
  if (disk_points > k_max_disk_points)
    throw UsageError("--max-n x --trials: the disk study would draw " + format("%.3g", disk_points) +
                     " points, above the limit of " + format("%.0e", k_max_disk_points) +
                     "; lower --max-n or --trials");
  if (ball_coordinates > k_max_ball_coordinates)
    throw UsageError("--ball-n x --trials x --dims: the ball study would draw " +
                     format("%.3g", ball_coordinates) + " coordinates, above the limit of " +
                     format("%.0e", k_max_ball_coordinates) + "; lower --ball-n, --trials or --dims");
  prepare_output_dir(o.common.out);

  ProgressBar progress("ch02 sampling", static_cast<std::uint64_t>(disk_points + ball_points),
                       o.common.quiet);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<ErrorRow> disk_rows = disk_error_study(disk_grid, o, progress);
  const double disk_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<ErrorRow> ball_rows = ball_table(o, progress);
  const std::vector<std::vector<ErrorRow>> ball_studies = ball_error_study(ball_grid, o, progress);
  progress.finish();
  const Picture picture = draw_points(o);

  const LineFit disk_fit = error_slope(disk_rows);
  std::vector<double> std_ratios;
  for (const ErrorRow& row : disk_rows) std_ratios.push_back(row.empirical_std / row.theory_std);
  const double median_std_ratio = median(std_ratios);
  const double samples_per_second = disk_points / disk_seconds;

  write_file_atomic(o.common.out / "disk_area.csv", disk_csv(disk_rows));
  write_file_atomic(o.common.out / "ball_volume.csv", ball_csv(o, ball_rows));
  write_file_atomic(o.common.out / "ball_error_vs_n.csv", ball_error_csv(ball_studies));
  write_file_atomic(o.common.out / "points.csv", picture.csv);
  write_plot(o.common.out, error_plot(disk_fit));
  write_plot(o.common.out, picture_plot(o, picture.estimate));
  write_plot(o.common.out, ball_error_plot());

  Json summary;
  summary["chapter"] = "ch02_disk_area";
  summary["seed"] = o.common.seed;
  summary["threads"] = o.common.threads;
  Json& disk = summary["disk"];
  disk["sizes"] = disk_grid.size();
  disk["trials"] = o.trials;
  disk["largest_n"] = o.max_n;
  disk["estimate_at_largest_n"] = disk_rows.back().mean_estimate;
  disk["fitted_slope"] = disk_fit.slope;
  disk["fitted_slope_standard_error"] = disk_fit.slope_standard_error;
  disk["theory_slope"] = -0.5;
  disk["median_empirical_over_theory_std"] = median_std_ratio;
  disk["samples"] = disk_points;
  disk["seconds"] = disk_seconds;
  disk["samples_per_second"] = samples_per_second;
  disk["avx2"] = disk_count_uses_avx2();
  Json& ball = summary["ball"];
  ball["n"] = o.ball_n;
  ball["trials"] = o.trials;
  for (std::size_t i = 0; i < ball_rows.size(); ++i)
    ball["volumes"].push_back({{"k", o.dims[i]},
                               {"exact_volume", unit_ball_volume(o.dims[i])},
                               {"mean_estimate", ball_rows[i].mean_estimate},
                               {"empirical_std", ball_rows[i].empirical_std},
                               {"theory_std", ball_rows[i].theory_std}});
  for (std::size_t s = 0; s < ball_studies.size(); ++s) {
    const LineFit fit = error_slope(ball_studies[s]);
    ball["fitted_slopes"].push_back({{"k", k_error_study_dims[s]},
                                     {"fitted_slope", fit.slope},
                                     {"fitted_slope_standard_error", fit.slope_standard_error}});
  }
  summary["picture"] = {{"points", o.points}, {"estimate", picture.estimate}};
  summary["flags"] = flags_json(app);
  write_json(o.common.out / "summary.json", summary);

  if (!o.common.quiet) {
    std::printf("ch02_disk_area  N from 10 to %llu (%zu sizes), %d trials each, seed %llu, "
                "%d threads\n",
                static_cast<unsigned long long>(o.max_n), disk_grid.size(), o.trials,
                static_cast<unsigned long long>(o.common.seed), o.common.threads);
    std::printf("  %12s  %10s  %10s  %10s  %10s\n", "N", "mean 4M/N", "rmse", "theory std",
                "emp/theory");
    for (std::size_t i = 0; i < disk_rows.size(); i += k_per_decade) {  // one row per decade
      const ErrorRow& r = disk_rows[i];
      std::printf("  %12llu  %10.6f  %10.3g  %10.3g  %10.3f\n",
                  static_cast<unsigned long long>(r.n), r.mean_estimate, r.rmse, r.theory_std,
                  r.empirical_std / r.theory_std);
    }
    std::printf("  slope of log(rmse) against log(N): %.3f +- %.3f  (theory -0.5)\n",
                disk_fit.slope, disk_fit.slope_standard_error);
    std::printf("  median empirical / theory std: %.3f\n", median_std_ratio);
    std::printf("  samples per second: %.3g  (%.3g points in %.2f s%s)\n", samples_per_second,
                disk_points, disk_seconds, disk_count_uses_avx2() ? ", AVX2" : "");
    std::printf("  k-ball at N = %llu:\n  %4s  %10s  %10s  %10s  %10s  %12s\n",
                static_cast<unsigned long long>(o.ball_n), "k", "exact V_k", "mean", "emp std",
                "theory std", "relative std");
    for (std::size_t i = 0; i < ball_rows.size(); ++i) {
      const ErrorRow& r = ball_rows[i];
      const double exact = unit_ball_volume(o.dims[i]);
      std::printf("  %4d  %10.6f  %10.6f  %10.3g  %10.3g  %12.3g\n", o.dims[i], exact,
                  r.mean_estimate, r.empirical_std, r.theory_std, r.theory_std / exact);
    }
    std::printf("  k-ball rmse slopes:");
    for (std::size_t s = 0; s < ball_studies.size(); ++s)
      std::printf("  k = %d: %.3f", k_error_study_dims[s], error_slope(ball_studies[s]).slope);
    std::printf("\n  picture: %d points, 4M/N = %.4f\n", o.points, picture.estimate);
    std::printf("  wrote %s/{disk_area,ball_volume,ball_error_vs_n,points}.csv, plots, "
                "summary.json\n",
                o.common.out.string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Chapter 02: the area of the unit disk by Monte Carlo (4 M / N from N uniform "
               "points of the square), its error against N, and the volume of the k-ball.",
               "ch02_disk_area"};
  Options o;
  add_common_options(app, o.common, Chapter{"ch02_disk_area", ""});
  app.add_option("--max-n", o.max_n, "Largest N of the 2D error study (N runs from 10)")
      ->check(CLI::Range(std::uint64_t{100}, std::uint64_t{1'000'000'000'000}));
  app.add_option("--trials", o.trials, "Independent estimates per N (2 or more: a variance needs 2)")
      ->check(CLI::Range(2, 100'000));
  app.add_option("--dims", o.dims, "Dimensions k of the ball table, e.g. 1,2,3")
      ->delimiter(',')
      ->check(CLI::Range(1, k_max_ball_dims));
  app.add_option("--ball-n", o.ball_n, "N of the ball table (and largest N of its error study)")
      ->check(CLI::Range(std::uint64_t{100}, std::uint64_t{1'000'000'000}));
  app.add_option("--points", o.points, "Points drawn in the picture")
      ->check(CLI::Range(1, 100'000));
  return run_chapter(app, argc, argv, [&] { return run(app, o); });
}
