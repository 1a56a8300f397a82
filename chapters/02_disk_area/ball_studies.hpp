#pragma once
// Chapter 02's studies of the k-ball: 2^k M / N at N = --ball-n for each k of --dims, and its
// error against N for k = 2, 5, 10 (the disk's loop in k dimensions, integration/ball.hpp).

#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "core/rng.hpp"
#include "integration/ball.hpp"
#include "integration/error_study.hpp"
#include "integration/statistics.hpp"
#include "io/table.hpp"
#include "plan.hpp"

namespace mcrt::ch02 {

// trials x (2^k M / N) at one N, estimate t from stream (key, t).
inline ErrorStats ball_trials(int k, std::uint64_t n, const auto& o, ProgressBar& progress,
                              std::uint64_t key) {
  return repeated_estimates(
      n, o.trials, unit_ball_volume(k), o.common.seed, o.common.threads, progress,
      [k](std::uint64_t m, Rng& rng) { return estimate_ball_volume(k, m, rng); },
      [key](std::uint64_t t) {
        return stream_key({{key, k_parts * k_indices}, {t, k_trials}});
      });
}

// 2. The k-ball at N = --ball-n for each k of --dims.
inline Table ball_study(const auto& o, ProgressBar& progress) {
  Table table({integer("k"), integer("n"), integer("trials"), real("exact_volume"),
               real("mean_estimate"), real("empirical_std"), real("theory_std"),
               real("relative_std")});
  for (int k : o.dims) {
    const auto kk = static_cast<std::uint64_t>(k);
    const ErrorStats e =
        ball_trials(k, o.ball_n, o, progress, stream_key({{ball_table, k_parts}, {kk, k_indices}}));
    const double exact = unit_ball_volume(k), theory = ball_volume_theory_std(k, o.ball_n);
    table.add_row({k, o.ball_n, o.trials, exact, e.mean(), e.stddev(), theory, theory / exact});
  }
  return table;
}

// 2b. rmse against N for k = 2, 5, 10, and each k's fitted slope of log(rmse) on log(N).
inline Table ball_error_study(const std::vector<std::uint64_t>& grid, const auto& o,
                              ProgressBar& progress, Table& slopes) {
  Table table({integer("k"), integer("n"), integer("trials"), real("mean_estimate"),
               real("empirical_std"), real("theory_std"), real("rmse"), real("exact_volume"),
               real("relative_theory_std"), real("relative_rmse")});
  for (int k : {2, 5, 10}) {
    const double exact = unit_ball_volume(k);
    std::vector<double> n, rmse;
    for (std::uint64_t i = 0; i < grid.size(); ++i) {
      const auto kk = static_cast<std::uint64_t>(k);
      const ErrorStats e =
          ball_trials(k, grid[i], o, progress,
                      stream_key({{ball_error, k_parts}, {kk, 1 << 16}, {i, 256}}));
      const double theory = ball_volume_theory_std(k, grid[i]);
      table.add_row({k, grid[i], o.trials, e.mean(), e.stddev(), theory, e.rmse(), exact,
                     theory / exact, e.rmse() / exact});
      n.push_back(static_cast<double>(grid[i]));
      rmse.push_back(e.rmse());
    }
    const LineFit fit = fit_log_log(n, rmse);
    slopes.add_row({k, fit.slope, fit.slope_standard_error});
  }
  return table;
}

}  // namespace mcrt::ch02
