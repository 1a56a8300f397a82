#pragma once
// Chapter 03's report: summary.json, timings.json and the console table, from the run's Plan
// and Results (errors, slopes and budget tables, seconds).

#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/cli.hpp"
#include "app/summary.hpp"
#include "study_plan.hpp"

namespace mcrt {

// summary.json: the setup, every study's reference, the slopes and the errors at the budget.
inline Json summary_of(const Chapter& chapter, const CLI::App& app, const auto& o, const Plan& plan,
                       const auto& r) {
  Json summary = start_summary(chapter.name, o.common.seed);
  summary["trials"] = o.trials;
  summary["max_evaluations"] = o.max_evaluations;
  summary["dims"] = o.dims;
  summary["evaluations"] = plan.total_evaluations;
  Json references = Json::object();
  for (const Study& study : plan.studies)
    references[study.name() + "_" + std::to_string(study.dims)] = reference(study);
  summary["references"] = references;
  summary["slopes"] = r.slopes.json();
  summary["at_budget"] = r.budget.json();
  summary["flags"] = flags_json(app);
  return summary;
}

// timings.json: the run's seconds and evaluations per second.
inline Json timings_of(const Chapter& chapter, const auto& o, const Plan& plan, const auto& r) {
  Json timings = start_timings(chapter.name, o.common.threads);
  timings["seconds"] = r.seconds;
  timings["evaluations_per_second"] = r.seconds > 0.0 ? plan.total_evaluations / r.seconds : 0.0;
  return timings;
}

// The console: the slopes table, the work and what was written.
inline void print_report(const Chapter& chapter, const auto& o, const Plan& plan, const auto& r) {
  fmt::print("{}  N up to {}  {} trials  k = {}  {} threads\n{}", chapter.name, o.max_evaluations,
             o.trials, fmt::join(o.dims, ","), o.common.threads,
             r.slopes.console({"integrand", "dims", "method", "fitted_slope", "standard_error",
                               "theory_slope"}));
  fmt::print(
      "  {:.3g} evaluations in {:.2f} s ({:.3g} per second)\n"
      "  wrote {}/{{errors,slopes,budget}}.csv, summary.json, timings.json and plots\n",
      plan.total_evaluations, r.seconds, r.seconds > 0.0 ? plan.total_evaluations / r.seconds : 0.0,
      o.common.out.string());
}

}  // namespace mcrt
