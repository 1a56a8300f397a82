#pragma once
// Chapter 09's tables, from the plan and one estimate per task: the rms error of every series
// at every N (disk.csv, smooth.csv), the fitted slopes (slopes.csv) and the dimension study
// at its budget (dimension.csv), with the trapezoid rule of chapter 03 beside it.

#include <cmath>
#include <cstdint>
#include <vector>

#include "integration/convergence.hpp"
#include "integration/quadrature.hpp"
#include "integration/statistics.hpp"
#include "io/table.hpp"
#include "plan.hpp"

namespace mcrt::ch09 {

inline Column text(const char* name) { return {name, Column::text}; }
inline Column integer(const char* name) { return {name, Column::integer}; }
inline Column real(const char* name, int digits = 6, Column::Style style = Column::scientific) {
  return {name, Column::real, digits, style};
}

// One error study's table: per series and N, the trials' mean and rms error, and the theory
// line: sigma / sqrt(N) for independent points (exact), else c N^predicted through the centre
// of the series' points (its slope is the prediction; only the constant is fitted).
inline Table error_table() {
  return Table({text("sampler"), integer("n"), integer("trials"),
                real("mean_estimate", 17, Column::general), real("rmse"), real("theory_line")});
}

inline Table slopes_table() {
  return Table({text("study"), text("sampler"), real("fitted_slope", 4, Column::fixed),
                real("standard_error", 4, Column::fixed), real("predicted_slope", 4, Column::fixed),
                integer("points")});
}

inline Table dimension_table() {
  return Table({integer("dims"), text("method"), integer("evaluations"), integer("points_per_axis"),
                real("mean_estimate", 17, Column::general), real("reference", 17, Column::general),
                real("rmse"), real("relative_error"), real("theory_rmse")});
}

struct Tables {
  Table disk = error_table(), smooth = error_table(), slopes = slopes_table(),
        dimension = dimension_table();
};

// Chapter 03's trapezoid rule at k: n = floor(budget^(1/k)) points per axis (n >= 2, else no
// row: the budget holds no grid), its error |T - I| in the rmse column.
inline void add_trapezoid_row(Table& dimension, int k, std::uint32_t budget) {
  const std::uint64_t n = points_per_axis_within(budget, k);
  if (n < 2) return;
  const GaussianProduct f{k};
  const double t = trapezoid(f, f.domain(), n), error = std::abs(t - f.reference());
  dimension.add_row({k, "trapezoid", grid_evaluations(n, k), n, t, f.reference(), error,
                     error / f.reference(), Cell{}});
}

// The trials of task range [first, first + trials) are one series at one N, in trial order.
inline Tables tabulate(const Plan& plan, const std::vector<double>& estimates, int trials,
                       std::uint32_t budget) {
  Tables tables;
  std::size_t task = 0;
  for (const Series& series : plan.series) {
    const Moments m = moments_of(series.study, series.dims);
    std::vector<double> n, rmse, mean;
    for (std::uint32_t size : series.sizes) {
      ErrorStats errors(m.integral);
      for (int t = 0; t < trials; ++t) errors.add(estimates[task++]);
      n.push_back(size);
      rmse.push_back(errors.rmse());
      mean.push_back(errors.mean());
    }
    if (series.study == Study::dimension) {
      const double theory = std::sqrt(m.variance / n[0]);
      tables.dimension.add_row({series.dims, name_of(series.sampler), series.sizes[0], Cell{},
                                mean[0], m.integral, rmse[0], rmse[0] / m.integral,
                                series.sampler == Sampler::independent ? Cell{theory} : Cell{}});
      continue;
    }
    const ErrorSlope slope = fit_error_slope(n, rmse, series.predicted_slope());
    Table& table = series.study == Study::disk ? tables.disk : tables.smooth;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const double line = series.sampler == Sampler::independent
                              ? std::sqrt(m.variance / n[i])
                              : slope.guide_constant * std::pow(n[i], series.predicted_slope());
      table.add_row({series.label(), series.sizes[i], trials, mean[i], rmse[i], line});
    }
    tables.slopes.add_row({name_of(series.study), series.label(), slope.fit.slope,
                           slope.fit.slope_standard_error, series.predicted_slope(), slope.points});
  }
  for (const Series& series : plan.series)  // the trapezoid rule at each k, after the sets
    if (series.study == Study::dimension && series.sampler == k_dimension_samplers[0])
      add_trapezoid_row(tables.dimension, series.dims, budget);
  return tables;
}

}  // namespace mcrt::ch09
