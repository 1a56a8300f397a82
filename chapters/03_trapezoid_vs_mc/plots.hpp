#pragma once
// Chapter 03's figures, written as gnuplot scripts over errors.csv and slopes.csv (columns
// by name).

#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "io/plot.hpp"
#include "io/table.hpp"

#include "study_plan.hpp"

namespace mcrt {

// One method's fitted slope, its theory, and c of the guide line c N^theory through the
// centre of its data.
struct SlopeLine {
  double fitted_slope;
  double theory;
  double constant;
};

// The errors.csv rows of one integrand, dimension and method: `value` where they match, else
// 1/0 (gnuplot skips the point). Used as the x value, so that the other rows do not widen the
// autoscaled x axis either.
inline std::string select_rows(const std::string& integrand, int dims, const char* method,
                               const char* value) {
  return fmt::format(
      "(strcol(\"integrand\") eq '{}' && column(\"dims\") == {} && "
      "strcol(\"method\") eq '{}' ? column(\"{}\") : 1/0)",
      integrand, dims, method, value);
}

// Error against N for one integrand: the trapezoid's |T - I|, Monte Carlo's rmse, and a line
// of each method's theoretical slope through the centre of its data.
inline Plot error_plot(const std::string& name, const std::string& title,
                       const std::string& integrand, int dims, const SlopeLine& trapezoid,
                       const SlopeLine& monte_carlo, const std::string& trapezoid_theory_label) {
  Plot plot;
  plot.name = name;
  plot.title = title;
  plot.x_label = "function evaluations N";
  plot.y_label = "error";
  plot.log_x = plot.log_y = true;
  plot.settings = fmt::format(
      "set key bottom left\nset autoscale xfix\n"
      "set style data linespoints\n"
      "c_trap = {:.17g}\nc_mc = {:.17g}\n",
      trapezoid.constant, monte_carlo.constant);
  plot.plot = fmt::format(
      "plot 'errors.csv' using {}:\"abs_error\" pt 7 lc rgb '#1f77b4' "
      "title 'trapezoid |Q_n - I| (slope {:.2f})', \\\n"
      "  '' using {}:\"rmse\" pt 5 lc rgb '#d62728' "
      "title 'Monte Carlo rmse (slope {:.2f})', \\\n"
      "  c_trap * x**({:.6g}) with lines dt 2 lc rgb '#1f77b4' title '{}', \\\n"
      "  c_mc * x**(-0.5) with lines dt 2 lc rgb '#d62728' title 'N^{{-1/2}}'",
      select_rows(integrand, dims, "trapezoid", "evaluations"), trapezoid.fitted_slope,
      select_rows(integrand, dims, "monte_carlo", "evaluations"), monte_carlo.fitted_slope,
      trapezoid.theory, trapezoid_theory_label);
  return plot;
}

// Fitted slope against k for both k-dimensional integrands and both methods, with the
// theory: -2/k and -1/k for the trapezoid rule, -1/2 for Monte Carlo. `dims`: the k of the
// k-dimensional studies, the x values drawn (the axis ends at the data's k).
inline Plot slopes_plot(const std::vector<double>& dims) {
  const auto series = [](const char* integrand, const char* method) {
    return fmt::format(
        "using (strcol(\"integrand\") eq '{}' && strcol(\"method\") eq '{}' ? "
        "column(\"dims\") : 1/0):\"fitted_slope\":\"standard_error\" "
        "with yerrorlines",
        integrand, method);
  };
  Plot plot;
  plot.name = "slopes_vs_k";
  plot.title = "Fitted slope of log(error) against log(N), by dimension D";
  plot.x_label = "dimension D";
  plot.y_label = "slope";
  plot.settings =
      "set key bottom right\nset autoscale xfix\nset yrange [-2.2:0.3]\n"
      "set xtics 1\nset samples 400\n";
  plot.x_values = dims;
  plot.plot = "plot 'slopes.csv' " + series("gaussian_kd", "trapezoid") +
              " pt 7 lc rgb '#1f77b4' title 'trapezoid, smooth (e^{-|x|^2})', \\\n"
              "  '' " +
              series("unit_ball_kd", "trapezoid") +
              " pt 9 lc rgb '#2ca02c' title 'trapezoid, ball indicator', \\\n"
              "  '' " +
              series("gaussian_kd", "monte_carlo") +
              " pt 5 lc rgb '#d62728' title 'Monte Carlo, smooth', \\\n"
              "  '' " +
              series("unit_ball_kd", "monte_carlo") +
              " pt 11 lc rgb '#ff7f0e' title 'Monte Carlo, ball indicator', \\\n"
              "  -2.0/x with lines dt 2 lc rgb '#1f77b4' title 'theory -2/D (smooth)', \\\n"
              "  -1.0/x with lines dt 2 lc rgb '#2ca02c' title 'theory -1/D (jump)', \\\n"
              "  -0.5 with lines dt 2 lc rgb '#d62728' title 'theory -1/2 (Monte Carlo)'";
  return plot;
}

// The curse of dimension at a fixed budget: each k-dimensional study's error at the largest N
// (budget.csv) relative to its integral I, the trapezoid rule's |T - I| / I on n =
// floor(budget^(1/k)) points per axis against Monte Carlo's rmse / I at N = budget, against k.
inline Plot budget_plot(std::uint64_t budget, const Table& at_budget) {
  const auto series = [](const char* integrand, const char* value) {
    return fmt::format(
        "using (strcol(\"integrand\") eq '{}' ? column(\"dims\") : 1/0):"
        "(column(\"{}\") / column(\"reference\")) with linespoints",
        integrand, value);
  };
  Plot plot;
  plot.name = "error_at_budget_vs_k";
  plot.title = fmt::format(
      "At a fixed budget of {} evaluations: relative error against "
      "dimension D",
      budget);
  plot.x_label = "dimension D";
  plot.y_label = "relative error at the budget (error / I)";
  plot.log_y = true;
  plot.settings = "set key bottom right\nset autoscale xfix\nset xtics 1\n";
  plot.x_values = at_budget.numbers("dims");
  const std::vector<double> reference = at_budget.numbers("reference");
  for (const char* column : {"trapezoid_error", "monte_carlo_rmse"}) {
    const std::vector<double> error = at_budget.numbers(column);
    for (std::size_t i = 0; i < error.size(); ++i) plot.y_values.push_back(error[i] / reference[i]);
  }
  plot.plot = "plot 'budget.csv' " + series("gaussian_kd", "trapezoid_error") +
              " pt 7 lw 2 lc rgb '#1f77b4' title 'trapezoid |Q_n - I| / I, smooth (e^{-|x|^2}), "
              "n = floor(budget^{1/D}) per axis', \\\n  '' " +
              series("unit_ball_kd", "trapezoid_error") +
              " pt 9 lw 2 lc rgb '#2ca02c' title 'trapezoid, ball indicator', \\\n"
              "  '' " +
              series("gaussian_kd", "monte_carlo_rmse") +
              " pt 5 lw 2 lc rgb '#d62728' title 'Monte Carlo rmse / I, smooth', \\\n"
              "  '' " +
              series("unit_ball_kd", "monte_carlo_rmse") +
              " pt 11 lw 2 lc rgb '#ff7f0e' title 'Monte Carlo, ball indicator'";
  return plot;
}

// The three error plots (studies 0 and 1 are the 1D integrands; the disk is the ball at
// k = 2) and the slopes against k.
inline void write_plots(const auto& o, const Plan& plan, const auto& r) {
  std::size_t disk = 0;
  for (std::size_t s = 0; s < plan.studies.size(); ++s)
    if (plan.studies[s].kind == Kind::unit_ball_kd && plan.studies[s].dims == k_disk_dims) disk = s;
  const auto plot = [&](const char* name, const char* title, std::size_t s, const char* label) {
    write_plot(o.common.dir, error_plot(name, title, plan.studies[s].name(), plan.studies[s].dims,
                                        r.lines[2 * s], r.lines[2 * s + 1], label));
  };
  plot("smooth_1d", "e^{-x^2} on [0,1]: error against N", 0, "N^{-2}");
  plot("discontinuous_1d", "ceil(sin x^2) on [0,3]: error against N", 1, "N^{-1}");
  plot("disk_2d", "Unit disk in [-1,1]^2: error against N", disk, "N^{-1/2} (n^{-1})");
  write_plot(o.common.dir, slopes_plot(r.budget.numbers("dims")));
  write_plot(o.common.dir, budget_plot(o.max_evaluations, r.budget));
}

}  // namespace mcrt
