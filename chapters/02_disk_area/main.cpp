// Chapter 02: the area of the unit disk by Monte Carlo, the lecture's first randomized
// algorithm (estimate_disk_area in common/integration/disk_area.hpp):
//
//   M = 0
//   for i < N:
//     x, y uniform in [-1, 1]
//     if x^2 + y^2 <= 1: M = M + 1
//   return 4 M / N
//
// Each point lands in the disk with probability p = pi/4, so M ~ Binomial(N, p),
// E[4M/N] = pi and V[4M/N] = 16 p (1 - p) / N: the error falls as N^-1/2. In k dimensions
// 2^k M / N estimates the ball's volume V_k with the same rate and a constant that grows
// quickly with k. The studies run the engine behind the loop, estimate_disk_area_fast
// (common/integration/disk_counter.hpp): the same count from the same streams, 16 points at
// a time.

#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "core/stopwatch.hpp"
#include "integration/ball.hpp"
#include "integration/disk_area.hpp"
#include "integration/disk_counter.hpp"
#include "integration/error_study.hpp"
#include "integration/log_grid.hpp"
#include "app/memory_limit.hpp"
#include "io/output.hpp"
#include "io/table.hpp"
#include "app/work_limit.hpp"
#include "app/summary.hpp"
#include "ball_studies.hpp"
#include "plan.hpp"
#include "plots.hpp"
#include "report.hpp"

using namespace mcrt;
using namespace mcrt::ch02;

namespace {

const Chapter k_chapter{"ch02_disk_area",
                        "Chapter 02: the area of the unit disk by Monte Carlo (4 M / N from N "
                        "uniform points of the square), its error against N, and the volume of "
                        "the k-ball."};

struct Options {
  CommonOptions common;
  std::uint64_t max_n = 10'000'000;  // largest N of the 2D error study (from N = 10)
  int trials = 100;                  // independent estimates per N
  std::vector<int> dims = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};  // k of the ball table
  std::uint64_t ball_n = 100'000;  // N of the ball table; largest N of the ball error study
  int points = 2000;               // points drawn in the picture
};

constexpr int k_per_decade = 4;  // sizes per factor of 10 on the N grids
// Limits on the work: ~10 minutes on 2 cores at the speeds this chapter measures.
constexpr double k_max_disk_points = 1e12;
constexpr double k_max_ball_coordinates = 1e11;

// 1. Error against N in 2D: trials x (4 M / N) at every N of the grid.
Table disk_study(const std::vector<std::uint64_t>& grid, const Options& o, ProgressBar& progress) {
  Table table({integer("n"), integer("trials"), real("mean_estimate"), real("bias"),
               real("empirical_std"), real("theory_std"), real("rmse")});
  for (std::uint64_t i = 0; i < grid.size(); ++i) {
    const ErrorStats e = repeated_estimates(
        grid[i], o.trials, k_pi, o.common.seed, o.common.threads, progress, estimate_disk_area_fast,
        [&](std::uint64_t t) {
          return stream_key({{disk_error, k_parts}, {i, k_indices}, {t, k_trials}});
        });
    table.add_row({grid[i], o.trials, e.mean(), e.bias(), e.stddev(), disk_area_theory_std(grid[i]),
                   e.rmse()});
  }
  return table;
}

// 3. The picture: --points points, inside or not, and their estimate 4 M / N.
Table draw_points(const Options& o, double& estimate) {
  Table table({{"x", Column::real, 6, Column::fixed},
               {"y", Column::real, 6, Column::fixed},
               integer("inside")});
  Rng rng(o.common.seed, stream_key({{picture, k_parts}, {0, k_indices}, {0, k_trials}}));
  int inside = 0;
  for (int i = 0; i < o.points; ++i) {
    const double point[2] = {2.0 * rng.uniform() - 1.0, 2.0 * rng.uniform() - 1.0};
    const bool in = inside_unit_ball(point);
    inside += in;
    table.add_row({point[0], point[1], in ? 1 : 0});
  }
  estimate = 4.0 * inside / o.points;
  return table;
}

// What the run found: every table, the disk's fit and its speed.
struct Results {
  Table disk, balls, ball_errors, ball_slopes, points;
  LineFit disk_fit;
  double disk_points = 0.0, disk_seconds = 0.0, median_std_ratio = 0.0, picture_estimate = 0.0;
};

// The work, refused before any is done if it is far too much: points of the disk study,
// coordinates of the balls.
Results run_studies(const Options& o) {
  const std::vector<std::uint64_t> disk_grid = log_grid(10, o.max_n, k_per_decade);
  const std::vector<std::uint64_t> ball_grid = log_grid(10, o.ball_n, k_per_decade);
  const double disk_points = o.trials * sum(disk_grid);
  const double ball_n = static_cast<double>(o.trials) * static_cast<double>(o.ball_n);
  const double dims_sum = std::accumulate(o.dims.begin(), o.dims.end(), 0.0);
  const double ball_coordinates = ball_n * dims_sum + (2 + 5 + 10) * o.trials * sum(ball_grid);
  check_work_limit({disk_points, "points", "--trials x the sizes of the N grid"}, k_max_disk_points,
                   "--max-n x --trials", "lower --max-n or --trials");
  check_work_limit({ball_coordinates, "coordinates", "--trials x N x k over the ball studies"},
                   k_max_ball_coordinates, "--ball-n x --trials x --dims",
                   "lower --ball-n, --trials or --dims");

  const double ball_points =
      ball_n * static_cast<double>(o.dims.size()) + 3 * o.trials * sum(ball_grid);
  ProgressBar progress("ch02 sampling", static_cast<std::uint64_t>(disk_points + ball_points),
                       o.common.quiet);
  const Stopwatch disk_clock;
  Table disk = disk_study(disk_grid, o, progress);
  const double disk_seconds = disk_clock.seconds();
  Table balls = ball_study(o, progress);
  Table ball_slopes({integer("k"), real("fitted_slope"), real("fitted_slope_standard_error")});
  Table ball_errors = ball_error_study(ball_grid, o, progress, ball_slopes);
  progress.finish();
  double picture_estimate = 0.0;
  Table points = draw_points(o, picture_estimate);

  const LineFit disk_fit = fit_log_log(disk.numbers("n"), disk.numbers("rmse"));
  std::vector<double> std_ratios = disk.numbers("empirical_std");
  const std::vector<double> theory_std = disk.numbers("theory_std");
  for (std::size_t i = 0; i < std_ratios.size(); ++i) std_ratios[i] /= theory_std[i];
  return {std::move(disk),
          std::move(balls),
          std::move(ball_errors),
          std::move(ball_slopes),
          std::move(points),
          disk_fit,
          disk_points,
          disk_seconds,
          median(std_ratios),
          picture_estimate};
}

void run(const CLI::App& app, const Options& o) {
  // No images: the program, its threads and its tables (a failed allocation still says why).
  check_memory_limit(images_in_memory(0.0, 0.0, o.common.threads, "the program and its threads"),
                     "--threads", "lower it");
  const Results r = run_studies(o);
  write_csv(o.common.dir / "disk_area.csv", r.disk);
  write_csv(o.common.dir / "ball_volume.csv", r.balls);
  write_csv(o.common.dir / "ball_error_vs_n.csv", r.ball_errors);
  write_csv(o.common.dir / "points.csv", r.points);
  write_plot(o.common.dir, error_plot(r.disk_fit.slope, 4.0 * disk_area_theory_std(1)));
  write_plot(o.common.dir, picture_plot(o.points, r.picture_estimate));
  write_plot(o.common.dir, ball_error_plot({2, 5, 10}));
  write_json(o.common.dir / "summary.json", summary_of(k_chapter, app, o, r));
  write_timings(o.common.dir, timings_of(k_chapter, o, r), run_flags_json(app));
  if (!o.common.quiet) print_report(k_chapter, o, r);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_number_option(app, "--max-n", o.max_n, "Largest N of the 2D error study (N runs from 10)",
                    std::uint64_t{100}, std::uint64_t{1'000'000'000'000});
  add_number_option(app, "--trials", o.trials,
                    "Independent estimates per N (2 or more: a variance needs 2)", 2, 100'000);
  add_list_option(app, "--dims", o.dims, "Dimensions k of the ball table, e.g. 1,2,3", 1,
                  k_max_ball_dims);
  add_number_option(app, "--ball-n", o.ball_n,
                    "N of the ball table (and largest N of its error study)", std::uint64_t{100},
                    std::uint64_t{1'000'000'000});
  add_number_option(app, "--points", o.points, "Points drawn in the picture", 1, 100'000);
  return app.run(argc, argv, [&] { run(app, o); });
}
