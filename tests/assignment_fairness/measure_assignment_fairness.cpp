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
// Course variants (make-assignment --variant) draw the statistical hidden tests' parameters from
// key.py's lists: with --variants (the file `key.py --hidden-grid` writes) each of those tests is
// measured again at every point of its grid (--variant-seeds seeds a point), so the figures
// hold for every variant, not only the default one.
//
// Two tests are thresholds, not p-values: a6's efficiency test fails ABOVE its limit (MIS's
// variance at equal rays more than 4x the better single strategy's in some region), a7's
// jittered rate test BELOW its limit (the variance of jittered points' estimate falling less than
// 64x from n = 16 to n = 256; its "p-value" is one-sided against a true fall of 64 while the
// solution's is about 253, so it is 1 at every seed and says nothing of a false-failure rate).
// Each one's ratio is measured per seed on the solution (a margin) and on its known bug (light
// sampling passed off as MIS; one jitter shared by every stratum): a detection. In
// fairness.json's "thresholds" the count says the direction: seeds_above_limit (a6) or
// seeds_below_limit (a7).
//
// Writes fairness.csv (one row per check or bug), fairness.json (the same rows by name, and a
// summary that docs/assignments/README.md quotes) and p_values.csv (every p-value). Seeds are keyed by row and index, never
// by thread: the files are the same whatever --threads.

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "app/cli.hpp"
#include "app/summary.hpp"
#include "assignment_fairness/known_bug_checks.hpp"
#include "assignment_fairness/measured_check.hpp"
#include "assignment_fairness/p_value_summary.hpp"
#include "assignment_fairness/solution_checks.hpp"
#include "assignments/hidden/fairness_p_values.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "io/output.hpp"
#include "io/table.hpp"
#include "stats/report.hpp"

using namespace mcrt;
using namespace mcrt::testing;
using namespace mcrt::testing::assignment;

namespace {

const Chapter k_program{
    "measure_assignment_fairness",
    "Measures the assignment grading's fairness: each statistical check's single-seed p-values "
    "on the solution (false failures, uniformity) and on every known bug (detection)."};

struct Options {
  CommonOptions common;
  int seeds = 1000;        // per check: a rate of 0.05 is then measured to +-0.007 (one sd)
  int region_seeds = 400;  // per region check (a reference render a seed): 0.05 to +-0.011
  int bug_seeds = 20;      // per known bug: all 20 rejecting puts its single-seed rate above 0.83
  int variant_seeds = 20;  // per point of a hidden test's variant grid (26 and 176 points)
  std::filesystem::path variants;  // key.py --hidden-grid's file; empty: no variant rows
  std::string filter;  // only the rows whose name contains this (a longer look at one check)
  bool quick = false;  // 20, 3, 3 and 1 seeds: seconds, for the smoke test
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

/// The variant grid of key.py --hidden-grid: {"a4": {"albedo": [...]}, "a5": {"roulette_q":
/// [...], "roulette_albedo": [...]}}. A missing or malformed file is a usage error.
HiddenGrid read_hidden_grid(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw UsageError(fmt::format("--variants {}: cannot be read", path.string()));
  const Json j = Json::parse(in, nullptr, false);
  const auto list = [&](const char* a, const char* name) {
    if (!j.is_object() || !j.contains(a) || !j[a].is_object() || !j[a].contains(name) ||
        !j[a][name].is_array() || j[a][name].empty())
      throw UsageError(fmt::format(
          "--variants {}: needs a non-empty list {}.{} (the file key.py --hidden-grid writes)",
          path.string(), a, name));
    std::vector<double> values;
    for (const Json& v : j[a][name]) {
      if (!v.is_number() || !(v.get<double>() > 0.0 && v.get<double>() < 1.0))
        throw UsageError(fmt::format("--variants {}: {}.{} holds {}, not a number in (0, 1)",
                                     path.string(), a, name, v.dump()));
      values.push_back(v.get<double>());
    }
    return values;
  };
  return {list("a4", "albedo"), list("a5", "roulette_q"), list("a5", "roulette_albedo")};
}

std::vector<Row> rows_of(const Options& o, const HiddenGrid& grid) {
  std::vector<Row> rows;
  std::vector<MeasuredCheck> checks = solution_checks();
  for (MeasuredCheck& c : hidden_variant_checks(subject(), grid)) checks.push_back(std::move(c));
  for (MeasuredCheck& c : checks) {
    const std::size_t points = variant_points(c.name, grid);
    const std::size_t n = points > 0
                              ? points * static_cast<std::size_t>(o.variant_seeds)
                              : static_cast<std::size_t>(c.region ? o.region_seeds : o.seeds);
    if (c.name.find(o.filter) == std::string::npos) continue;
    rows.push_back({false,
                    c.name,
                    c.test,
                    c.name,
                    c.alpha,
                    c.majority,
                    true,
                    n,
                    c.region,
                    std::move(c.p_value),
                    {},
                    {}});
  }
  for (MeasuredBug& b : known_bugs()) {
    if (b.name.find(o.filter) == std::string::npos) continue;
    const std::size_t n = b.p_value ? static_cast<std::size_t>(o.bug_seeds) : 1;
    rows.push_back({true,
                    b.name,
                    b.test,
                    b.check,
                    k_seed_alpha,
                    true,
                    b.expected,
                    n,
                    b.region,
                    std::move(b.p_value),
                    std::move(b.fails),
                    {}});
  }
  return rows;
}

/// The side of its limit on which a threshold test fails.
enum class FailsWhen { above, below };

/// A threshold test's ratio at one seed: a6's efficiency test (the largest ratio over the regions
/// of MIS's variance, balance heuristic, to the better single strategy's; fails above 4) or a7's
/// jittered rate test (the variance at n = 16 over that at n = 256; fails below 64).
struct ThresholdRow {
  std::string name, test;
  bool bug = false;  // a known bug: every seed should be on the failing side of the limit
  double limit = 0.0;
  FailsWhen fails = FailsWhen::above;
  std::size_t seeds = 0;
  std::function<double(std::uint64_t)> ratio;
  std::vector<double> ratios;
};

std::vector<ThresholdRow> threshold_rows_of(const Options& o) {
  const auto ratio_of = [](auto producer) {
    return [producer](std::uint64_t seed) {
      std::size_t where = 0;
      return mis_variance_ratio(producer, A6Strategy::mis_balance, seed, where);
    };
  };
  const auto n = static_cast<std::size_t>(o.region_seeds);
  const auto bug_seeds = static_cast<std::size_t>(o.bug_seeds);
  std::vector<ThresholdRow> rows{{"a6_efficiency",
                                  "a6.A6.Task3MisBeatsEachStrategyAtEqualRays",
                                  false,
                                  k_a6_variance_factor,
                                  FailsWhen::above,
                                  n,
                                  [](std::uint64_t seed) {
                                    std::size_t where = 0;
                                    return mis_variance_ratio(subject(), A6Strategy::mis_balance,
                                                              seed, where);
                                  },
                                  {}},
                                 {"a6_light_sampling_passed_off_as_mis",
                                  diagnosis_test("A6LightSamplingPassedOffAsMis"),
                                  true,
                                  k_a6_variance_factor,
                                  FailsWhen::above,
                                  bug_seeds,
                                  ratio_of(light_sampling_as_mis()),
                                  {}},
                                 {"a7_jittered_rate",
                                  "a7.A7.Task1JitteredVarianceFallsAsOneOverNSquared",
                                  false,
                                  k_a7_rate_limit,
                                  FailsWhen::below,
                                  static_cast<std::size_t>(o.seeds),
                                  [](std::uint64_t seed) {
                                    return jittered_rate(subject(), seed).ratio;
                                  },
                                  {}},
                                 {"a7_jitter_shared_by_every_stratum",
                                  diagnosis_test("A7JitterSharedByEveryStratum"),
                                  true,
                                  k_a7_rate_limit,
                                  FailsWhen::below,
                                  bug_seeds,
                                  [](std::uint64_t seed) {
                                    auto wrong = a7_with<JitterSharedByEveryStratum>();
                                    return jittered_rate(wrong, seed).ratio;
                                  },
                                  {}}};
  std::erase_if(rows,
                [&](const ThresholdRow& t) { return t.name.find(o.filter) == std::string::npos; });
  return rows;
}

/// Every (row, seed index) once, the region renders first (the longest jobs: started first,
/// they do not leave one thread working alone at the end), in parallel over --threads.
void measure(std::vector<Row>& rows, std::vector<ThresholdRow>& thresholds, const Options& o) {
  // (row, seed index); a threshold row is numbered after the p-value rows
  std::vector<std::pair<std::size_t, std::size_t>> jobs;
  for (std::size_t t = 0; t < thresholds.size(); ++t)  // renders too: first
    for (std::size_t i = 0; i < thresholds[t].seeds; ++i) jobs.emplace_back(rows.size() + t, i);
  for (bool region : {true, false})
    for (std::size_t r = 0; r < rows.size(); ++r)
      if (rows[r].region == region)
        for (std::size_t i = 0; i < rows[r].seeds; ++i) jobs.emplace_back(r, i);
  for (Row& row : rows) row.p_values.assign(row.seeds, 1.0);
  for (ThresholdRow& t : thresholds) t.ratios.assign(t.seeds, 0.0);
  ProgressBar progress("fairness", jobs.size(), o.common.quiet);
  parallel_for(jobs.size(), o.common.threads, [&](std::size_t j) {
    const auto [r, i] = jobs[j];
    if (r >= rows.size()) {
      ThresholdRow& t = thresholds[r - rows.size()];
      t.ratios[i] = t.ratio(o.common.seed + i);
    } else {
      Row& row = rows[r];
      row.p_values[i] = row.p_value ? row.p_value(o.common.seed + i) : (row.fails() ? 0.0 : 1.0);
    }
    progress.advance();
  });
  progress.finish();
}

/// A threshold row in fairness.json: its ratios' spread and how many seeds lie on the failing
/// side of the limit (seeds_above_limit or seeds_below_limit, which names the direction). a6's
/// test fails a seed exactly there (2 of 3 seeds fail the test). a7's rejects a seed only when
/// the ratio is significantly below 64 (p < 5e-4: below about 46), so counting against 64 is the
/// stricter count. A ratio that is not a number counts as failing, as in the tests.
Json threshold_json(const ThresholdRow& t) {
  std::vector<double> sorted = t.ratios;
  std::sort(sorted.begin(), sorted.end());
  const bool above = t.fails == FailsWhen::above;
  const auto failing =
      static_cast<std::size_t>(std::count_if(sorted.begin(), sorted.end(), [&](double r) {
        return above ? !(r <= t.limit) : !(r >= t.limit);
      }));
  return {{"test", t.test},
          {"known_bug", t.bug},
          {"limit", t.limit},
          {"seeds", t.seeds},
          {"min_ratio", sorted.front()},
          {"median_ratio", sorted[sorted.size() / 2]},
          {"max_ratio", sorted.back()},
          {above ? "seeds_above_limit" : "seeds_below_limit", failing}};
}

/// A variant row's grid, point by point: how its seeds' p-values spread (each point holds
/// every points-th seed), for the README's "at every variant".
Json variant_json(const Row& row, std::size_t points, std::uint64_t first_seed) {
  std::vector<std::size_t> seeds(points, 0), below5(points, 0);
  for (std::size_t i = 0; i < row.p_values.size(); ++i) {
    const std::size_t point = grid_point(first_seed + i, points);
    ++seeds[point];
    below5[point] += row.p_values[i] < 0.05;
  }
  double low = 1.0, high = 0.0;
  for (std::size_t k = 0; k < points; ++k) {
    const double f =
        static_cast<double>(below5[k]) / static_cast<double>(std::max<std::size_t>(seeds[k], 1));
    low = std::min(low, f), high = std::max(high, f);
  }
  return {{"points", points},
          {"seeds_per_point", row.p_values.size() / points},
          {"fraction_below_5_percent_lowest_point", low},
          {"fraction_below_5_percent_highest_point", high}};
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
    const std::string verdict = exact          ? "exact"
                                : row.majority ? fmt::format("2 of 3 seeds below {}", row.alpha)
                                               : fmt::format("1 fixed seed below {}", row.alpha);
    // Cell by cell: one initializer list of cells with empty ones trips a false
    // -Wmaybe-uninitialized in g++ 12.
    std::vector<Cell> cells;
    const auto put = [&cells](Cell c) { cells.push_back(std::move(c)); };
    const auto blank = [&put](int n) {
      for (int i = 0; i < n; ++i) put(Cell{});
    };
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
  double low5 = 1.0, high5 = 0.0, low1 = 1.0, high1 = 0.0, min_p = 1.0, min_ks_p = 1.0,
         hidden_min_p = 1.0;
  double min_ks_p_without_regions = 1.0;
  std::uint64_t bugs = 0, bugs_detected = 0, exact_bugs = 0, exact_detected = 0,
                undetected_expected = 0;
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
  const double pooled_upper =
      binomial_confidence_interval(below_alpha, p_values, k_bound_level).high;
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
Json json_of(const CLI::App& app, const Options& o, const Table& table,
             const std::vector<Row>& rows, const std::vector<ThresholdRow>& thresholds,
             const HiddenGrid& grid) {
  Json j;
  j["program"] = k_program.name;
  j["first_seed"] = o.common.seed;
  j["flags"] = flags_json(app);
  // the counts run (--quick replaces the flags' values)
  j["seeds"] = {{"check", o.seeds},
                {"region_check", o.region_seeds},
                {"bug", o.bug_seeds},
                {"variant_point", o.variant_seeds}};
  j["grading"] = {{"seeds", k_seeds}, {"alpha", k_seed_alpha}};
  j["summary"] = summary_of(rows);
  Json variants = Json::object(), limits = Json::object();
  for (const Row& row : rows)
    if (const std::size_t points = variant_points(row.name, grid); points > 0)
      variants[row.name] = variant_json(row, points, o.common.seed);
  for (const ThresholdRow& t : thresholds) limits[t.name] = threshold_json(t);
  j["variants"] = variants;
  j["thresholds"] = limits;
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
  if (o.quick) o.seeds = 20, o.region_seeds = 3, o.bug_seeds = 3, o.variant_seeds = 1;
  const HiddenGrid grid = o.variants.empty() ? HiddenGrid{} : read_hidden_grid(o.variants);
  const std::size_t largest_grid = std::max(grid.a4_albedo.size(), grid.a5_points());
  const auto most =
      std::max(static_cast<std::uint64_t>(std::max({o.seeds, o.region_seeds, o.bug_seeds})),
               static_cast<std::uint64_t>(largest_grid) *
                   static_cast<std::uint64_t>(o.variant_seeds));
  if (o.common.seed > UINT64_MAX - most)
    throw UsageError(fmt::format("--seed: {} + {} seeds passes 2^64", o.common.seed, most));
  for (std::uint64_t g : k_grading_seeds)
    if (g >= o.common.seed && g < o.common.seed + most)
      throw UsageError(fmt::format(
          "--seed: the seeds {} to {} include the grading seed {}; the measurement needs "
          "seeds the tests do not use (the default starts at {})",
          o.common.seed, o.common.seed + most - 1, g, k_first_seed));
  set_failure_reports(false);  // the bugs fail by design: their heat maps would only be noise
  std::vector<Row> rows = rows_of(o, grid);
  std::vector<ThresholdRow> thresholds = threshold_rows_of(o);
  measure(rows, thresholds, o);
  const Table table = fairness_table(rows);
  write_csv(o.common.dir / "fairness.csv", table);
  write_file_atomic(o.common.dir / "p_values.csv", p_values_csv(rows, o.common.seed));
  const Json json = json_of(app, o, table, rows, thresholds, grid);
  write_json(o.common.dir / "fairness.json", json);
  if (!o.common.quiet) {
    std::fputs(table
                   .console({"name", "seeds", "fraction_below_5_percent",
                             "fraction_below_1_percent", "below_alpha", "min_p", "ks_p",
                             "rejected_seeds", "max_p"})
                   .c_str(),
               stdout);
    std::printf("%s\n%s\n%s\n", json["summary"].dump(1).c_str(), json["variants"].dump(1).c_str(),
                json["thresholds"].dump(1).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  o.common.seed = k_first_seed;
  ChapterApp app(k_program, o.common);
  add_number_option(app, "--seeds", o.seeds, "Seeds per check on the solution", 3, 100000);
  add_number_option(app, "--region-seeds", o.region_seeds,
                    "Seeds per region check (a reference render per seed, about a second each)", 3,
                    100000);
  add_number_option(app, "--bug-seeds", o.bug_seeds, "Seeds per known bug", 1, 1000);
  add_number_option(app, "--variant-seeds", o.variant_seeds,
                    "Seeds per point of a hidden test's variant grid (with --variants)", 1, 1000);
  CLI::App& flags = app;  // a text flag: no add_*_option of app/cli.hpp reads one
  flags.add_option("--filter", o.filter,
                   "Only the rows (checks, bugs, thresholds) whose name contains this text");
  add_path_option(
      app, "--variants", o.variants,
      "The hidden tests' variant grid: the file `tests/assignments/answers/key.py --hidden-grid` "
      "writes (default: none, the default variant only)");
  flags.add_flag(
      "--quick", o.quick,
      "20 seeds per check, 3 per region check and per bug, 1 per variant point (seconds)");
  return app.run(argc, argv, [&] { run(app, o); });
}
