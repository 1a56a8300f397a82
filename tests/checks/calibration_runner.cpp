// Calibration of the statistical checks: how often does each one fail on correct code?
//
// A check with false-failure rate alpha returns p-values that are Uniform(0,1) when the code
// is right, so over S independent seeds:
//   - its rejections at alpha, at 0.05 and at 0.01 are Binomial(S, rate) counts, tested with
//     the exact two-sided binomial test (at alpha = 1e-4 a few hundred seeds expect ~0
//     rejections, so the larger rates are where the calibration has power);
//   - the p-values pass a Kolmogorov-Smirnov test of uniformity.
// A check is consistent with its design when all four tests accept at level
// a = sidak_alpha(0.01, 4 x checks): the whole calibration run then fails by chance with
// probability at most 1%. The run exits with code 3 if any check is inconsistent.
// A check designed as "at most alpha" (MCRT_STATISTICAL_CHECK_AT_MOST: a Sidak combination of
// correlated statistics) is held to the one-sided versions: no rate significantly above its
// level, no p-values significantly smaller than uniform ones.
//
// Seeds: every check first runs on a pilot of 20 seeds, which also times it; then each check
// gets as many seeds as the time budget (--budget seconds for the whole run) allows, at least
// --min-seeds and at most --seeds, the cheap checks first and the leftover time passed on to
// the expensive ones. Seed i is always the same number, so a check's result for a given seed
// count is reproducible; only the count can depend on the machine's speed.
//
// It writes into --out: calibration.csv (the table), p_values.csv (every p-value) and the
// plot p_value_cdf.{gp,png,svg}: each check's empirical CDF of p-values, which should hug the
// diagonal.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/cli.hpp"
#include "core/parallel.hpp"
#include "core/progress.hpp"
#include "core/rng.hpp"
#include "io/output.hpp"
#include "io/plot.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"
#include "stats/report.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

struct Options {
  CommonOptions common;
  int seeds = 1000;     // at most: a rejection rate of 0.05 is then measured to +-0.007
  int min_seeds = 200;  // at least: ... to +-0.015; a 1% KS test sees a CDF off by 0.12
  double budget = 240;  // seconds of wall time for the whole run, pilots included
  std::string filter;   // run only the checks whose name contains this
};

// Seeds every check runs first, to time it.
constexpr int k_pilot_seeds = 20;

// --filter TEXT: the names that contain TEXT; TEXT$: those that end with it (one check whose
// name is the start of another's: nee_..._cornell but not nee_..._cornell_spheres).
bool filter_matches(const std::string& filter, const std::string& name) {
  if (!filter.empty() && filter.back() == '$') {
    const std::string end = filter.substr(0, filter.size() - 1);
    return name.size() >= end.size() &&
           name.compare(name.size() - end.size(), end.size(), end) == 0;
  }
  return name.find(filter) != std::string::npos;
}

// The i-th calibration seed: mix64 of the i-th step of a Weyl sequence, so seeds are spread
// over 64 bits and unrelated to the suite's seed.
std::uint64_t calibration_seed(std::uint64_t base, std::uint64_t i) {
  return mix64(base + 0x9e3779b97f4a7c15ULL * (i + 1));
}

struct Rate {
  double level = 0.0;
  std::uint64_t rejections = 0;
  double p_value = 1.0;  // exact binomial test of rejections against level
};

struct Calibration {
  const StatisticalCheck* check = nullptr;
  std::vector<double> p_values;  // one per seed
  Rate at_alpha, at_5_percent, at_1_percent;
  double ks_statistic = 0.0, ks_p = 1.0;
  double seconds = 0.0;
  bool consistent = true;
  std::string error;  // a check that threw
};

Rate rejection_rate(const std::vector<double>& p_values, double level) {
  Rate rate{level};
  for (double p : p_values) rate.rejections += p < level ? 1 : 0;
  rate.p_value = binomial_test_p_value(rate.rejections, p_values.size(), level);
  return rate;
}

// p-values of `check` at calibration seeds [first, first + count), in parallel over seeds.
void run_seeds(const StatisticalCheck& check, const Options& o, std::size_t first,
               std::size_t count, std::vector<double>& p_values, ProgressBar* progress) {
  p_values.resize(first + count, 1.0);
  parallel_for(count, o.common.threads, [&](std::size_t i) {
    p_values[first + i] = check.p_value(calibration_seed(o.common.seed, first + i));
    if (progress) progress->advance();
  });
}

// The pilot: the first seeds, timed.
Calibration pilot(const StatisticalCheck& check, const Options& o) {
  Calibration c;
  c.check = &check;
  const auto start = std::chrono::steady_clock::now();
  try {
    run_seeds(check, o, 0, k_pilot_seeds, c.p_values, nullptr);
  } catch (const std::exception& e) {
    c.error = e.what();
    c.consistent = false;
  }
  c.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

// Seeds per check within the budget: cheapest first, each taking an equal share of what is
// left (clamped to [min_seeds, seeds]), so the time cheap checks do not use goes to the rest.
// `left` is the seconds left for checks first.. (the pilots already run); `slowdown` scales the
// pilots' costs by how much slower the finished checks ran than their pilots predicted (a
// machine that got busier), so the run keeps to its budget.
std::vector<int> allocate_seeds(const std::vector<Calibration>& pilots, std::size_t first,
                                double left, double slowdown, const Options& o) {
  std::vector<double> cost(pilots.size());  // seconds per seed
  for (std::size_t k = 0; k < pilots.size(); ++k)
    cost[k] = slowdown * std::max(pilots[k].seconds, 1e-6) / k_pilot_seeds;
  std::vector<std::size_t> order;
  for (std::size_t k = first; k < pilots.size(); ++k) order.push_back(k);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return cost[a] < cost[b]; });
  std::vector<int> seeds(pilots.size(), o.min_seeds);
  for (std::size_t r = 0; r < order.size(); ++r) {
    const std::size_t k = order[r];
    const double share = std::max(0.0, left) / static_cast<double>(order.size() - r);
    const double affordable = share / cost[k] + k_pilot_seeds;
    seeds[k] = static_cast<int>(
        std::clamp(affordable, static_cast<double>(o.min_seeds), static_cast<double>(o.seeds)));
    left -= (seeds[k] - k_pilot_seeds) * cost[k];
  }
  return seeds;
}

// For an "at most alpha" design: P(X >= k) for X ~ Binomial(n, rate), the chance of k or more
// rejections at the designed rate, is at least `level`.
bool rejections_not_too_many(std::size_t k, std::size_t n, double rate, double level) {
  double tail = 0.0;
  const auto total = static_cast<double>(n);
  for (std::size_t j = k; j <= n; ++j) {
    const auto hits = static_cast<double>(j);
    const double log_term = std::lgamma(total + 1.0) - std::lgamma(hits + 1.0) -
                            std::lgamma(total - hits + 1.0) + hits * std::log(rate) +
                            (total - hits) * std::log1p(-rate);
    tail += std::exp(log_term);
    if (hits > total * rate && std::exp(log_term) < 1e-18) break;
  }
  return k == 0 || tail >= level;
}

// The one-sided Kolmogorov-Smirnov test of the p-values against uniform: D+ = max (i/n - x_(i)),
// the empirical CDF above the uniform's (p-values too small), with Smirnov's P(D+ >= d) about
// exp(-2 n d^2).
bool p_values_not_too_small(std::vector<double> p_values, double level) {
  std::sort(p_values.begin(), p_values.end());
  const double n = static_cast<double>(p_values.size());
  double d = 0.0;
  for (std::size_t i = 0; i < p_values.size(); ++i)
    d = std::max(d, static_cast<double>(i + 1) / n - std::clamp(p_values[i], 0.0, 1.0));
  return std::exp(-2.0 * n * d * d) >= level;
}

// The rest of the seeds, then the rates and the KS test.
void finish(Calibration& c, int seeds, const Options& o, double level, ProgressBar& progress) {
  if (!c.error.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  try {
    run_seeds(*c.check, o, k_pilot_seeds, static_cast<std::size_t>(seeds - k_pilot_seeds),
              c.p_values, &progress);
  } catch (const std::exception& e) {
    c.error = e.what();
    c.consistent = false;
    return;
  }
  c.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  c.at_alpha = rejection_rate(c.p_values, c.check->alpha);
  c.at_5_percent = rejection_rate(c.p_values, 0.05);
  c.at_1_percent = rejection_rate(c.p_values, 0.01);
  c.ks_statistic = uniformity_ks_statistic(c.p_values);
  c.ks_p = ks_p_value(c.ks_statistic, c.p_values.size());
  c.consistent = c.at_alpha.p_value >= level && c.at_5_percent.p_value >= level &&
                 c.at_1_percent.p_value >= level && c.ks_p >= level;
  if (c.check->at_most) {  // only too many rejections, and too small p-values, count
    const std::size_t n = c.p_values.size();
    c.consistent = rejections_not_too_many(c.at_alpha.rejections, n, c.check->alpha, level) &&
                   rejections_not_too_many(c.at_5_percent.rejections, n, 0.05, level) &&
                   rejections_not_too_many(c.at_1_percent.rejections, n, 0.01, level) &&
                   p_values_not_too_small(c.p_values, level);
  }
}

std::string rate_cell(const Rate& r, std::size_t seeds) {
  char text[64];
  std::snprintf(text, sizeof text, "%llu (%.4f)", static_cast<unsigned long long>(r.rejections),
                static_cast<double>(r.rejections) / static_cast<double>(seeds));
  return text;
}

void print_table(const std::vector<Calibration>& rows, double level) {
  std::printf(
      "Calibration: rejections (rate) on correct code; consistency level a = %.2g per "
      "test (Sidak: 1%% for the whole run)\n",
      level);
  int width = 5;
  for (const Calibration& c : rows) width = std::max(width, static_cast<int>(c.check->name.size()));
  std::printf("%-*s %7s %6s %14s %14s %14s %7s %7s %8s %s\n", width, "check", "alpha", "seeds",
              "rej@alpha", "rej@0.05", "rej@0.01", "KS D", "KS p", "seconds", "verdict");
  for (const Calibration& c : rows) {
    if (!c.error.empty()) {
      std::printf("%-*s %7.0e  error: %s\n", width, c.check->name.c_str(), c.check->alpha,
                  c.error.c_str());
      continue;
    }
    const auto n = c.p_values.size();
    std::printf("%-*s %7.0e %6zu %14s %14s %14s %7.4f %7.3f %8.2f %s\n", width,
                c.check->name.c_str(), c.check->alpha, n, rate_cell(c.at_alpha, n).c_str(),
                rate_cell(c.at_5_percent, n).c_str(), rate_cell(c.at_1_percent, n).c_str(),
                c.ks_statistic, c.ks_p, c.seconds, c.consistent ? "consistent" : "INCONSISTENT");
  }
}

void write_outputs(const std::filesystem::path& dir, const std::vector<Calibration>& rows,
                   std::uint64_t base_seed) {
  prepare_output_dir(dir);
  std::ostringstream table, all, cdf;
  table << "check,alpha,seeds,rejections_at_alpha,rate_at_alpha,binomial_p_at_alpha,"
           "rejections_at_0.05,rate_at_0.05,binomial_p_at_0.05,rejections_at_0.01,"
           "rate_at_0.01,binomial_p_at_0.01,ks_statistic,ks_p,seconds,consistent\n";
  all << "check,seed,p_value\n";
  for (const Calibration& c : rows) {
    const double n = static_cast<double>(c.p_values.size());
    table << c.check->name << ',' << c.check->alpha << ',' << c.p_values.size();
    for (const Rate* r : {&c.at_alpha, &c.at_5_percent, &c.at_1_percent})
      table << ',' << r->rejections << ',' << static_cast<double>(r->rejections) / n << ','
            << r->p_value;
    table << ',' << c.ks_statistic << ',' << c.ks_p << ',' << c.seconds << ','
          << (c.consistent ? "yes" : "no") << '\n';
    for (std::size_t i = 0; i < c.p_values.size(); ++i)
      all << c.check->name << ',' << calibration_seed(base_seed, i) << ',' << c.p_values[i] << '\n';
  }
  // Empirical CDFs: for each check a pair of columns (sorted p-value, fraction i/S); a check
  // with fewer seeds leaves its cells empty in the last rows.
  std::vector<std::vector<double>> sorted;
  std::size_t longest = 0;
  for (const Calibration& c : rows) {
    cdf << (sorted.empty() ? "" : ",") << c.check->name << ",fraction";
    sorted.push_back(c.p_values);
    std::sort(sorted.back().begin(), sorted.back().end());
    longest = std::max(longest, sorted.back().size());
  }
  cdf << '\n';
  for (std::size_t i = 0; i < longest; ++i) {
    for (std::size_t k = 0; k < sorted.size(); ++k) {
      const auto n = sorted[k].size();
      cdf << (k == 0 ? "" : ",");
      if (i < n)
        cdf << sorted[k][i] << ',' << static_cast<double>(i + 1) / static_cast<double>(n);
      else
        cdf << ',';
    }
    cdf << '\n';
  }
  write_file_atomic(dir / "calibration.csv", table.str());
  write_file_atomic(dir / "p_values.csv", all.str());
  write_file_atomic(dir / "p_value_cdf.csv", cdf.str());

  Plot plot;
  plot.name = "p_value_cdf";
  plot.title = "Empirical CDF of each check's p-values on correct code (ideal: the diagonal)";
  plot.x_label = "p-value";
  plot.y_label = "fraction of seeds with a smaller p-value";
  plot.settings =
      "set key outside right font ',8' noenhanced\nset xrange [0:1]\n"
      "set yrange [0:1]\n";
  plot.plot = "plot for [i=1:" + std::to_string(2 * rows.size()) +
              ":2] 'p_value_cdf.csv' using i:i+1 with lines title columnhead(i), "
              "x with lines dt 2 lc 'black' "
              "title 'Uniform(0,1)'";
  plot.width = 1200;
  write_plot(dir, plot);
}

int run(const CLI::App& app, Options o) {
  // Without an explicit --min-seeds, a small --seeds lowers the floor with it.
  if (app.count("--min-seeds") == 0) o.min_seeds = std::min(o.min_seeds, o.seeds);
  std::vector<const StatisticalCheck*> checks;
  for (const StatisticalCheck& check : statistical_checks())
    if (filter_matches(o.filter, check.name)) checks.push_back(&check);
  if (checks.empty()) throw UsageError("--filter: no check name contains '" + o.filter + "'");
  if (o.min_seeds > o.seeds)
    throw UsageError("--min-seeds: " + std::to_string(o.min_seeds) + " is above --seeds " +
                     std::to_string(o.seeds));
  prepare_output_dir(o.common.out);

  // The run provokes many designed failures; their reports would only be noise.
  set_failure_reports(false);
  const double level = sidak_alpha(0.01, 4 * static_cast<int>(checks.size()));
  const auto start = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<Calibration> rows;
  for (const StatisticalCheck* check : checks) rows.push_back(pilot(*check, o));
  const double pilots_seconds = seconds_since_start();
  // The plan at the pilots' speed; each check is planned again before it runs, from the time
  // left and the speed measured so far, never above its first plan (the progress bar's total).
  const std::vector<int> planned = allocate_seeds(rows, 0, o.budget - pilots_seconds, 1.0, o);
  std::uint64_t total = 0;
  for (int n : planned) total += static_cast<std::uint64_t>(n - k_pilot_seeds);
  ProgressBar progress("calibration", total, o.common.quiet);
  double predicted = 0.0, spent = 0.0;  // seconds of the finished checks' extra seeds
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double slowdown = predicted > 0.0 ? std::max(1.0, spent / predicted) : 1.0;
    const std::vector<int> seeds =
        allocate_seeds(rows, k, o.budget - seconds_since_start(), slowdown, o);
    const int n = std::min(seeds[k], planned[k]);
    const double pilot_seconds = rows[k].seconds;
    finish(rows[k], n, o, level, progress);
    predicted += pilot_seconds / k_pilot_seeds * (n - k_pilot_seeds);
    spent += rows[k].seconds - pilot_seconds;
  }
  progress.finish();

  write_outputs(o.common.out, rows, o.common.seed);
  if (!o.common.quiet) print_table(rows, level);
  const auto inconsistent =
      std::count_if(rows.begin(), rows.end(), [](const Calibration& c) { return !c.consistent; });
  std::cout << (inconsistent == 0
                    ? "all " + std::to_string(rows.size()) +
                          " checks are consistent with their design"
                    : std::to_string(inconsistent) + " of " + std::to_string(rows.size()) +
                          " checks are INCONSISTENT with their design")
            << "; table in " << (o.common.out / "calibration.csv").string() << "\n";
  return inconsistent == 0 ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Runs every statistical check over many seeds on the correct code and compares "
      "its rejection rates and p-values with its design (exit code 3 if they differ).",
      "calibrate_statistical_checks"};
  Options o;
  add_common_options(app, o.common, Chapter{"calibration", ""});
  app.add_option("--seeds", o.seeds, "Most seeds per check")->check(CLI::Range(100, 100000));
  app.add_option("--min-seeds", o.min_seeds, "Fewest seeds per check, whatever the budget")
      ->check(CLI::Range(k_pilot_seeds, 100000));
  app.add_option("--budget", o.budget, "Seconds the whole run should take (a target)")
      ->check(CLI::Range(1.0, 86400.0));
  app.add_option("--filter", o.filter,
                 "Run only the checks whose name contains this text (TEXT$: ends with it)");
  return run_chapter(app, argc, argv, [&] { return run(app, o); });
}
