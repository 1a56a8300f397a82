// Fairness of the assignment grading, measured (issue #33, docs/assignments/README.md
// "Fairness"): how often does each statistical check fail the correct solution, and how often
// does it catch each known bug?
//
// A statistical task test runs its check at three grading seeds and fails when two reject at
// alpha = 5e-4 (assignments/grading.hpp). Its promise, a false-failure rate of
// 3 alpha^2 (1 - alpha) + alpha^3 = 7.5e-7, holds if the check's single-seed p-value is
// Uniform(0, 1) on a correct solution. So for every check this program runs that single-seed
// p-value, through the same function the test calls, on the solution (LocalSubject) at seeds
// --seed, --seed + 1, ... (disjoint from the grading seeds), and records how many fall below
// 0.05, 0.01 and alpha, the smallest, and a Kolmogorov-Smirnov test of uniformity. For every
// known bug of tests/assignments/diagnosis_test.cpp it runs the check that bug fails at a few
// seeds: the largest p-value, and how many seeds reject (detection). Bugs caught by an exact
// check (ray counts, exact furnace paths, a pdf's integral) are run once.
//
// Writes fairness.csv (one row per check or bug), fairness.json (the same rows by name, and a
// summary that docs/assignments/README.md quotes) and p_values.csv (every p-value). Seeds are keyed by row and index, never
// by thread: the files are the same whatever --threads.

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "assignment_fairness/known_bug_checks.hpp"
#include "assignment_fairness/measured_check.hpp"
#include "assignment_fairness/p_value_summary.hpp"
#include "assignment_fairness/solution_checks.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "io/cli.hpp"
#include "io/output.hpp"
#include "io/summary.hpp"
#include "io/table.hpp"
#include "stats/report.hpp"

using namespace mcrt;
using namespace mcrt::testing;
using namespace mcrt::testing::assignment;

namespace {

const Chapter k_program{"measure_assignment_fairness",
                        "Measures the assignment grading's fairness: each statistical check's single-seed p-values "
                        "on the solution (false failures, uniformity) and on every known bug (detection)."};

struct Options {
  CommonOptions common;
  int seeds = 1000;        // per check: a rate of 0.05 is then measured to +-0.007 (one sd)
  int region_seeds = 400;  // per region check (a reference render a seed): 0.05 to +-0.011
  int bug_seeds = 20;      // per known bug: all 20 rejecting puts its single-seed rate above 0.83
  bool quick = false;      // 20, 3 and 3 seeds: seconds, for the smoke test
};

// The first seed: far above the grading seeds (1009, 2029, 3037) and the hidden tests' own.
constexpr std::uint64_t k_first_seed = 100000;

/// One row of fairness.csv: a check on the solution, or a known bug through a check.
struct Row {
  bool bug = false;
  std::string name, test, check;
  double alpha = k_seed_alpha;
  bool majority = true;
  bool expected = true;
  std::size_t seeds = 0;
  bool region = false;
  std::function<double(std::uint64_t)> p_value;  // empty for an exact check
  std::function<bool()> fails;
  std::vector<double> p_values;  // one per seed; an exact check's: 0 if it fails, 1 if not
};

std::vector<Row> rows_of(const Options& o) {
  std::vector<Row> rows;
  for (MeasuredCheck& c : solution_checks()) {
    const int n = c.region ? o.region_seeds : o.seeds;
    rows.push_back({false, c.name, c.test, c.name, c.alpha, c.majority, true, static_cast<std::size_t>(n), c.region,
                    std::move(c.p_value), {}, {}});
  }
  for (MeasuredBug& b : known_bugs()) {
    const std::size_t n = b.p_value ? static_cast<std::size_t>(o.bug_seeds) : 1;
    rows.push_back({true, b.name, b.test, b.check, k_seed_alpha, true, b.expected, n, b.region, std::move(b.p_value),
                    std::move(b.fails), {}});
  }
  return rows;
}

/// Every (row, seed index) once, the region renders first (the longest jobs: started first,
/// they do not leave one thread working alone at the end), in parallel over --threads.
void measure(std::vector<Row>& rows, const Options& o) {
  std::vector<std::pair<std::size_t, std::size_t>> jobs;
  for (bool region : {true, false})
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r].region == region)
        for (std::size_t i = 0; i < rows[r].seeds; ++i) jobs.emplace_back(r, i);
  for (Row& row : rows) row.p_values.assign(row.seeds, 1.0);
  ProgressBar progress("fairness", jobs.size(), o.common.quiet);
  parallel_for(jobs.size(), o.common.threads, [&](std::size_t j) {
    const auto [r, i] = jobs[j];
    Row& row = rows[r];
    row.p_values[i] = row.p_value ? row.p_value(o.common.seed + i) : (row.fails() ? 0.0 : 1.0);
    progress.advance();
  });
  progress.finish();
}

Table fairness_table(const std::vector<Row>& rows) {
  Table t({{"row", Column::text},
           {"name", Column::text},
           {"test", Column::text},
           {"check", Column::text},
           {"verdict", Column::text},
           {"alpha", Column::real, 3},
           {"seeds", Column::integer},
           {"below_5_percent", Column::integer},
           {"fraction_below_5_percent", Column::real, 6},
           {"below_1_percent", Column::integer},
           {"fraction_below_1_percent", Column::real, 6},
           {"below_alpha", Column::integer},
           {"min_p", Column::real, 6},
           {"ks_statistic", Column::real, 6},
           {"ks_p", Column::real, 6},
           {"alpha_rate_upper_95", Column::real, 6},
           {"majority_failure_rate", Column::real, 6},
           {"majority_failure_upper_95", Column::real, 6},
           {"expected_detection", Column::text},
           {"rejected_seeds", Column::integer},
           {"max_p", Column::real, 6},
           {"detection_lower_95", Column::real, 6},
           {"majority_detection_lower_95", Column::real, 6}});
  for (const Row& row : rows) {
    const bool exact = !row.p_value;
    const std::string verdict = exact ? "exact"
                                : row.majority ? fmt::format("2 of 3 seeds below {}", row.alpha)
                                               : fmt::format("1 fixed seed below {}", row.alpha);
    // Cell by cell: one initializer list of cells with empty ones trips a false
    // -Wmaybe-uninitialized in g++ 12.
    std::vector<Cell> cells;
    const auto put = [&cells](Cell c) { cells.push_back(std::move(c)); };
    const auto blank = [&put](int n) { for (int i = 0; i < n; ++i) put(Cell{}); };
    put(row.bug ? "bug" : "check");
    put(row.name);
    put(row.test);
    put(row.check);
    put(verdict);
    put(exact ? Cell{} : Cell{row.alpha});
    put(row.seeds);
    if (!row.bug) {
      const FalseFailures f = false_failures(row.p_values, row.alpha);
      const double n = static_cast<double>(f.seeds);
      put(f.below_5_percent);
      put(static_cast<double>(f.below_5_percent) / n);
      put(f.below_1_percent);
      put(static_cast<double>(f.below_1_percent) / n);
      put(f.below_alpha);
      put(f.min_p);
      put(f.ks_statistic);
      put(f.ks_p);
      put(f.rate_alpha_upper);
      put(row.majority ? Cell{f.majority_rate} : Cell{});
      put(row.majority ? Cell{f.majority_rate_upper} : Cell{});
      blank(5);
    } else {
      const Detection d = detection(row.p_values, row.alpha);
      blank(11);
      put(row.expected ? "yes" : "no");
      put(d.rejected);
      put(exact ? Cell{} : Cell{d.max_p});
      put(exact ? Cell{} : Cell{d.rate_lower});
      put(exact ? Cell{} : Cell{d.majority_rate_lower});
    }
    t.add_row(std::move(cells));
  }
  return t;
}

/// What the README quotes: the checks graded by a majority of three, pooled, and the bugs.
Json summary_of(const std::vector<Row>& rows) {
  std::uint64_t checks = 0, p_values = 0, below_alpha = 0, region_checks = 0, hidden = 0;
  double low5 = 1.0, high5 = 0.0, low1 = 1.0, high1 = 0.0, min_p = 1.0, min_ks_p = 1.0, hidden_min_p = 1.0;
  double min_ks_p_without_regions = 1.0;
  std::uint64_t bugs = 0, bugs_detected = 0, exact_bugs = 0, exact_detected = 0, undetected_expected = 0;
  double bug_max_p = 0.0;
  for (const Row& row : rows) {
    if (!row.bug) {
      const FalseFailures f = false_failures(row.p_values, row.alpha);
      min_ks_p = std::min(min_ks_p, f.ks_p);
      if (!row.region) min_ks_p_without_regions = std::min(min_ks_p_without_regions, f.ks_p);
      if (!row.majority) {
        ++hidden;
        hidden_min_p = std::min(hidden_min_p, f.min_p);
        continue;
      }
      const double n = static_cast<double>(f.seeds);
      ++checks;
      region_checks += row.region;
      p_values += f.seeds;
      below_alpha += f.below_alpha;
      low5 = std::min(low5, static_cast<double>(f.below_5_percent) / n);
      high5 = std::max(high5, static_cast<double>(f.below_5_percent) / n);
      low1 = std::min(low1, static_cast<double>(f.below_1_percent) / n);
      high1 = std::max(high1, static_cast<double>(f.below_1_percent) / n);
      min_p = std::min(min_p, f.min_p);
    } else if (row.expected) {
      const Detection d = detection(row.p_values, row.alpha);
      const bool all = d.rejected == d.seeds;
      if (row.p_value) {
        ++bugs;
        bugs_detected += all;
        bug_max_p = std::max(bug_max_p, d.max_p);
      } else {
        ++exact_bugs;
        exact_detected += all;
      }
      undetected_expected += !all;
    }
  }
  const double pooled_upper = binomial_confidence_interval(below_alpha, p_values, k_bound_level).high;
  Json s;
  s["majority_checks"] = checks;
  s["majority_region_checks"] = region_checks;
  s["majority_p_values"] = p_values;
  s["majority_below_alpha"] = below_alpha;
  s["majority_expected_below_alpha"] = k_seed_alpha * static_cast<double>(p_values);
  s["fraction_below_5_percent_lowest"] = low5;
  s["fraction_below_5_percent_highest"] = high5;
  s["fraction_below_1_percent_lowest"] = low1;
  s["fraction_below_1_percent_highest"] = high1;
  s["majority_min_p"] = min_p;
  s["min_ks_p"] = min_ks_p;
  s["min_ks_p_without_regions"] = min_ks_p_without_regions;
  s["pooled_alpha_rate_upper_95"] = pooled_upper;
  s["pooled_majority_failure_upper_95"] = majority_false_failure_rate(pooled_upper);
  s["design_majority_failure_rate"] = majority_false_failure_rate();
  s["hidden_checks"] = hidden;
  s["hidden_min_p"] = hidden_min_p;
  s["statistical_bugs"] = bugs;
  s["statistical_bugs_detected_at_every_seed"] = bugs_detected;
  s["statistical_bugs_max_p"] = bug_max_p;
  s["exact_bugs"] = exact_bugs;
  s["exact_bugs_detected"] = exact_detected;
  s["expected_bugs_missed_at_some_seed"] = undetected_expected;
  return s;
}

/// p_values.csv: every p-value, by row and seed (to look at a distribution the table sums up).
std::string p_values_csv(const std::vector<Row>& rows, std::uint64_t first_seed) {
  std::string text = "name,seed,p_value\n";
  for (const Row& row : rows)
    if (row.p_value)
      for (std::size_t i = 0; i < row.p_values.size(); ++i)
        text += fmt::format("{},{},{:.9g}\n", row.name, first_seed + i, row.p_values[i]);
  return text;
}

/// fairness.json: the flags, the grading rule, the summary, and every row by name.
Json json_of(const CLI::App& app, const Options& o, const Table& table, const std::vector<Row>& rows) {
  Json j;
  j["program"] = k_program.name;
  j["first_seed"] = o.common.seed;
  j["flags"] = flags_json(app);
  // the counts run (--quick replaces the flags' values)
  j["seeds"] = {{"check", o.seeds}, {"region_check", o.region_seeds}, {"bug", o.bug_seeds}};
  j["grading"] = {{"seeds", k_seeds}, {"alpha", k_seed_alpha}};
  j["summary"] = summary_of(rows);
  Json checks = Json::object(), bugs = Json::object();
  for (const Json& row : table.json()) {
    Json fields = Json::object();
    for (const auto& [key, value] : row.items())
      if (key != "row" && key != "name" && !value.is_null()) fields[key] = value;
    (row["row"] == "bug" ? bugs : checks)[row["name"].get<std::string>()] = fields;
  }
  j["checks"] = checks;
  j["bugs"] = bugs;
  return j;
}

void run(const CLI::App& app, Options o) {
  if (o.quick) o.seeds = 20, o.region_seeds = 3, o.bug_seeds = 3;
  const auto most = static_cast<std::uint64_t>(std::max({o.seeds, o.region_seeds, o.bug_seeds}));
  if (o.common.seed > UINT64_MAX - most)
    throw UsageError(fmt::format("--seed: {} + {} seeds passes 2^64", o.common.seed, most));
  for (std::uint64_t g : k_grading_seeds)
    if (g >= o.common.seed && g < o.common.seed + most)
      throw UsageError(fmt::format("--seed: the seeds {} to {} include the grading seed {}; the measurement needs "
                                   "seeds the tests do not use (the default starts at {})",
                                   o.common.seed, o.common.seed + most - 1, g, k_first_seed));
  set_failure_reports(false);  // the bugs fail by design: their heat maps would only be noise
  std::vector<Row> rows = rows_of(o);
  measure(rows, o);
  const Table table = fairness_table(rows);
  write_csv(o.common.dir / "fairness.csv", table);
  write_file_atomic(o.common.dir / "p_values.csv", p_values_csv(rows, o.common.seed));
  const Json json = json_of(app, o, table, rows);
  write_json(o.common.dir / "fairness.json", json);
  if (!o.common.quiet) {
    std::fputs(table.console({"name", "seeds", "fraction_below_5_percent", "fraction_below_1_percent", "below_alpha",
                              "min_p", "ks_p", "rejected_seeds", "max_p"})
                   .c_str(),
               stdout);
    std::printf("%s\n", json["summary"].dump(1).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  o.common.seed = k_first_seed;
  ChapterApp app(k_program, o.common);
  add_number_option(app, "--seeds", o.seeds, "Seeds per check on the solution", 3, 100000);
  add_number_option(app, "--region-seeds", o.region_seeds,
                    "Seeds per region check (a reference render per seed, about a second each)", 3, 100000);
  add_number_option(app, "--bug-seeds", o.bug_seeds, "Seeds per known bug", 1, 1000);
  CLI::App& cli = app;  // the flag has no add_*_option of io/cli.hpp
  cli.add_flag("--quick", o.quick, "20 seeds per check, 3 per region check and per bug (seconds)");
  return app.run(argc, argv, [&] { run(app, o); });
}
