#pragma once
// Chapter 06's splitting study (splitting.csv, splitting.png): roulette's counterpart in the
// furnace. For each q of --split-q and each n of --split: the first hit goes on as n paths of
// 1/n of its weight, each a fixed-q roulette path after d bounces (common/render/splitting.hpp);
// efficiency = 1 / (variance x rays per path), in rays so that it is the same in every run
// with the seed, against its closed form.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "integration/statistics.hpp"
#include "io/plot.hpp"
#include "io/table.hpp"
#include "render/russian_roulette.hpp"
#include "render/splitting.hpp"

#include "furnace_studies.hpp"

namespace mcrt {

// Stream blocks of the splitting rows (+ the row): far above the efficiency sweep's 16 + row.
inline constexpr std::uint64_t k_splitting_block = std::uint64_t{1} << 20;
// The study splits the first hit only: splitting deeper multiplies every later ray by n again
// for less and less variance (splitting.hpp's Var_j), as the page's under-the-hood note shows.
inline constexpr int k_split_depth = 1;

// Paths of a row that splits n ways: --paths / n (at least 100), so that every row traces about
// the same rays.
inline int split_row_paths(int paths, int n) { return std::max(100, paths / n); }

// splitting.csv: one row per (q, n), q of `split_q`, n of `split_n`.
inline Table splitting_study(const Furnace& f, const std::vector<double>& split_q,
                             const std::vector<int>& split_n) {
  Table table({{"q", Column::real, 4},
               {"n", Column::integer},
               {"paths", Column::integer},
               {"mean", Column::real},
               {"variance", Column::real},
               {"variance_theory", Column::real},
               {"rays_per_path", Column::real, 6},
               {"rays_per_path_theory", Column::real, 6},
               {"efficiency", Column::real, 6},
               {"efficiency_theory", Column::real, 6}});
  const int d = f.roulette.min_depth;
  std::uint64_t row = 0;
  for (double q : split_q)
    for (int n : split_n) {
      const Roulette roulette{d, RoulettePolicy::fixed, q, f.roulette.floor};
      const Splitting splitting{k_split_depth, n};
      const int paths = split_row_paths(f.paths, n);
      const std::vector<FurnacePath> traced =
          trace_furnace_paths(static_cast<std::uint64_t>(paths), f.seed, k_splitting_block + row++,
                              f.threads, [&](const Ray& ray, Rng& rng, RayCount& count) {
                                return estimate_path_radiance_splitting(f.scene, ray, roulette,
                                                                        splitting, rng, count);
                              });
      RunningStats radiance, rays;
      for (const FurnacePath& path : traced) {
        radiance.add(path.radiance);
        rays.add(static_cast<double>(path.rays));
      }
      // The closed forms hold for s <= d and q > 4a^2/3; elsewhere the cell stays empty.
      const bool known = k_split_depth <= d && q > furnace_roulette_variance_threshold(f.albedo);
      const auto theory = [&](double x) { return known ? Cell(x) : Cell(); };
      const double variance = furnace_splitting_variance(f.albedo, f.emission, d, q, splitting);
      const double length = furnace_splitting_mean_rays(d, q, splitting);
      table.add_row({q, n, paths, radiance.mean(), radiance.variance(), theory(variance),
                     rays.mean(), theory(length), 1.0 / (radiance.variance() * rays.mean()),
                     theory(1.0 / (variance * length))});
    }
  return table;
}

// splitting.png: efficiency against n, one colour per q: measured (points) and the closed form
// n / (V_roulette(q) (1 + n (d - 1 + 1/(1 - q)))) of splitting the first hit (dashed).
inline void write_splitting_plot(const std::filesystem::path& out, double albedo, double emission,
                                 int min_depth, const std::vector<double>& split_q,
                                 const Table& splitting) {
  std::string plots;
  for (std::size_t i = 0; i < split_q.size(); ++i) {
    const double q = split_q[i];
    plots += fmt::format(
        "{}'splitting.csv' using (abs(column(\"q\") - {q:.9g}) < 1e-9 ? column(\"n\") : NaN):"
        "\"efficiency\" with points pt 7 ps 1.5 lc {lc} title 'q = {q:g}, measured', "
        "eff(x, {q:.9g}) with lines dt 2 lw 2 lc {lc} title 'q = {q:g}, closed form'",
        i == 0 ? "plot " : ", ", fmt::arg("q", q), fmt::arg("lc", i + 1));
  }
  Plot plot{"splitting",
            "Splitting the first hit n ways, fixed-q roulette after d: 1 / (variance x rays)",
            "n (paths the first hit goes on as)",
            "efficiency (1 / (variance x rays))",
            true,
            false,
            fmt::format("a = {:.9g}; Le = {:.9g}; d = {}\n"
                        "b = 4.0 * a**2 / 3\n"
                        "S(q) = (1 - b**(d + 1)) / (1 - b) + b**(d + 1) / (q - b)\n"
                        "V(q) = Le**2 * ((1 + a) / (1 - a) * S(q) - 1 / (1 - a)**2)\n"
                        "eff(n, q) = (q > b && d >= 1) ? n / (V(q) * (1 + n * (d - 1 + 1 / "
                        "(1 - q)))) : NaN\n"
                        "set logscale x 2\nset format x '%g'\nset xtics 2\nset autoscale xfix\n"
                        "set key bottom right\n"
                        "set samples 200\n",
                        albedo, emission, min_depth),
            plots};
  plot.y_values = {0.0};
  for (double y : splitting.numbers("efficiency"))
    if (std::isfinite(y)) plot.y_values.push_back(y);
  for (double x : splitting.numbers("n")) plot.x_values.push_back(x);
  write_plot(out, plot);
}

}  // namespace mcrt
