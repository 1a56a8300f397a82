#pragma once
// Chapter 09's report: summary.json (per study and sampler the fitted slope, its standard
// error, the prediction and the rms error at the largest N; the dimension study and the gain
// of each point set over independent points at every k), timings.json and the console.

#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli.hpp"
#include "app/summary.hpp"
#include "plan.hpp"
#include "tables.hpp"

namespace mcrt::ch09 {

// The rms error of `label` at the largest N of an error table.
inline double rmse_at_largest_n(const Table& errors, const std::string& label) {
  double rmse = 0.0;
  for (std::size_t r = 0; r < errors.size(); ++r)
    if (errors.at(r, "sampler").csv(0) == label) rmse = errors.numbers("rmse")[r];
  return rmse;
}

// Per k, independent points' rms error over each other method's: how many times better.
inline Json gains(const Table& dimension) {
  Json gains = Json::array();
  const std::vector<double> k = dimension.numbers("dims"), rmse = dimension.numbers("rmse");
  for (std::size_t r = 0; r < dimension.size(); ++r) {
    if (dimension.at(r, "method").csv(0) != "independent") continue;
    Json row = {{"dims", static_cast<int>(k[r])}};
    for (std::size_t o = 0; o < dimension.size(); ++o)
      if (k[o] == k[r] && o != r) row[dimension.at(o, "method").csv(0)] = rmse[r] / rmse[o];
    gains.push_back(row);
  }
  return gains;
}

inline Json summary_of(const Chapter& chapter, const CLI::App& app, const auto& o, const Plan& plan,
                       const Tables& t) {
  Json summary = start_summary(chapter.name, o.common.seed);
  summary["trials"] = o.trials;
  summary["max_n"] = o.max_n;
  summary["budget"] = o.budget;
  summary["dims"] = o.dims;
  summary["points"] = plan.points;
  for (const char* study : {"disk", "smooth"}) {
    Json entries = Json::object();
    const Table& errors = std::string(study) == "disk" ? t.disk : t.smooth;
    for (std::size_t r = 0; r < t.slopes.size(); ++r) {
      if (t.slopes.at(r, "study").csv(0) != study) continue;
      const std::string label = t.slopes.at(r, "sampler").csv(0);
      entries[label] = {{"fitted_slope", t.slopes.numbers("fitted_slope")[r]},
                        {"fitted_slope_standard_error", t.slopes.numbers("standard_error")[r]},
                        {"predicted_slope", t.slopes.numbers("predicted_slope")[r]},
                        {"rmse_at_largest_n", rmse_at_largest_n(errors, label)}};
    }
    summary[study] = entries;
  }
  summary["dimension"] = {{"budget", o.budget},
                          {"errors", t.dimension.json()},
                          {"gain_over_independent", gains(t.dimension)}};
  summary["flags"] = flags_json(app);
  return summary;
}

inline Json timings_of(const Chapter& chapter, const auto& o, const Plan& plan, double seconds) {
  Json timings = start_timings(chapter.name, o.common.threads);
  timings["seconds"] = seconds;
  timings["points_per_second"] = seconds > 0.0 ? plan.points / seconds : 0.0;
  return timings;
}

inline void print_report(const Chapter& chapter, const auto& o, const Plan& plan, const Tables& t,
                         double seconds) {
  fmt::print("{}  N = 16..{}  {} randomisations  budget {} at D = {}  {} threads\n{}", chapter.name,
             o.max_n, o.trials, o.budget, fmt::join(o.dims, ","), o.common.threads,
             t.slopes.console());
  fmt::print("  at N = {}:\n{}", o.budget,
             t.dimension.console({"dims", "method", "evaluations", "rmse", "relative_error"}));
  fmt::print(
      "  {:.3g} points in {:.2f} s\n  wrote {}/{{disk,smooth,slopes,dimension,points}}.csv, "
      "plots, summary.json, timings.json\n",
      plan.points, seconds, o.common.out.string());
}

}  // namespace mcrt::ch09
