#pragma once
// Chapter 06's three furnace studies, where E[L] = Le / (1 - a) and the closed forms of
// common/render/russian_roulette.hpp are known: the depth cut's bias against roulette's, the
// efficiency of each q, and the path lengths. Each returns its Table (bias.csv, efficiency.csv,
// path_length.csv).

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/stopwatch.hpp"
#include "integration/statistics.hpp"
#include "io/table.hpp"
#include "render/path_tracer.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"

namespace mcrt {

// bias.csv's intervals are mean +- 3.29 standard errors (99.9%): over 11 rows, some row's
// interval misses the truth in about 1% of runs.
inline constexpr double k_ci_z = 3.2905267;
// Stream blocks of the studies: each study draws its own paths. The bias study uses one block
// for every k, so its rows share their paths and the curve is smooth.
inline constexpr std::uint64_t k_cut_block = 1, k_roulette_block = 2, k_length_block = 3;
inline constexpr std::uint64_t k_efficiency_block = 16;  // + the row

// The furnace of --albedo and --emission, what the studies ask of it, and its paths.
struct Furnace {
  Scene scene;
  double albedo = 0.5, emission = 1.0;
  int paths = 0;  // paths per row of every study
  std::uint64_t seed = 1;
  int threads = 1;
  int depth = 10;         // the largest k of the bias study
  Roulette roulette;      // the bias study's policy; d and --fixed-q of the other two
  std::vector<double> q;  // the efficiency sweep

  template <class Estimator>
  std::vector<FurnacePath> trace(std::uint64_t block, Estimator&& estimate) const {
    return trace_furnace_paths(static_cast<std::uint64_t>(paths), seed, block, threads, estimate);
  }
  auto depth_cut(int k) const {
    return [this, k](const Ray& ray, Rng& rng, RayCount& count) {
      return estimate_path_radiance(scene, ray, k, rng, count);
    };
  }
  auto with_roulette(const Roulette& r) const {
    return [this, r](const Ray& ray, Rng& rng, RayCount& count) {
      return estimate_path_radiance_roulette(scene, ray, r, rng, count);
    };
  }
};

struct PathStats {
  RunningStats radiance, rays;
  double seconds = 0.0;
};

template <class Estimator>
inline PathStats measure(const Furnace& furnace, std::uint64_t block, Estimator&& estimate) {
  const Stopwatch clock;
  const std::vector<FurnacePath> paths = furnace.trace(block, estimate);
  PathStats stats;
  stats.seconds = clock.seconds();
  for (const FurnacePath& path : paths) {
    stats.radiance.add(path.radiance);
    stats.rays.add(static_cast<double>(path.rays));
  }
  return stats;
}

// bias.csv: the depth cut at k and roulette after k bounces, against Le / (1 - a).
inline Table bias_study(const Furnace& f) {
  Table bias({{"k", Column::integer},
              {"cut_mean", Column::real},
              {"cut_bias", Column::real},
              {"cut_ci", Column::real},
              {"cut_bias_theory", Column::real},
              {"roulette_mean", Column::real},
              {"roulette_bias", Column::real},
              {"roulette_ci", Column::real},
              {"roulette_rays_per_path", Column::real, 6}});
  const double exact = furnace_radiance_untruncated(f.albedo, f.emission);
  for (int k = 0; k <= f.depth; ++k) {
    const PathStats cut = measure(f, k_cut_block, f.depth_cut(k));
    Roulette after_k = f.roulette;
    after_k.min_depth = k;
    const PathStats roulette = measure(f, k_roulette_block, f.with_roulette(after_k));
    bias.add_row({k, cut.radiance.mean(), cut.radiance.mean() - exact,
                  k_ci_z * cut.radiance.standard_error(),
                  furnace_depth_cut_bias(f.albedo, f.emission, k), roulette.radiance.mean(),
                  roulette.radiance.mean() - exact, k_ci_z * roulette.radiance.standard_error(),
                  roulette.rays.mean()});
  }
  return bias;
}

// efficiency.csv: one row per fixed q, then the throughput policy; efficiency = 1 / (variance x
// seconds per path), and its closed form at the sweep's mean seconds per ray.
inline Table efficiency_study(const Furnace& f) {
  std::vector<PathStats> rows;
  for (std::size_t i = 0; i < f.q.size(); ++i) {
    const Roulette fixed{f.roulette.min_depth, RoulettePolicy::fixed, f.q[i], f.roulette.floor};
    rows.push_back(measure(f, k_efficiency_block + i, f.with_roulette(fixed)));
  }
  Roulette throughput = f.roulette;
  throughput.policy = RoulettePolicy::throughput;
  rows.push_back(measure(f, k_efficiency_block + f.q.size(), f.with_roulette(throughput)));

  double seconds = 0.0, rays = 0.0;
  for (const PathStats& r : rows) seconds += r.seconds, rays += r.rays.mean() * f.paths;
  const double seconds_per_ray = seconds / rays;
  const auto efficiency = [&](const PathStats& r) {
    return 1.0 / (r.radiance.variance() * r.seconds / f.paths);
  };
  // The best q: the most efficient of those with a finite variance (q > 4a^2/3), whose
  // sample variance means something; of all of them if none has.
  const double b = furnace_roulette_variance_threshold(f.albedo);
  const bool any_finite = f.q.back() > b;
  std::size_t best = f.q.size();
  for (std::size_t i = 0; i < f.q.size(); ++i)
    if ((f.q[i] > b || !any_finite) &&
        (best == f.q.size() || efficiency(rows[i]) > efficiency(rows[best])))
      best = i;

  Table table({{"policy", Column::text},
               {"q", Column::real, 4},
               {"mean", Column::real},
               {"variance", Column::real},
               {"variance_theory", Column::real},
               {"rays_per_path", Column::real, 6},
               {"rays_per_path_theory", Column::real, 6},
               {"seconds", Column::real, 4},
               {"efficiency", Column::real, 6},
               {"efficiency_theory", Column::real, 6},
               {"best_efficiency", Column::integer}});
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const PathStats& r = rows[i];
    const bool fixed = i < f.q.size();
    const double var =
        fixed ? furnace_roulette_variance(f.albedo, f.emission, f.roulette.min_depth, f.q[i])
              : std::nan("");
    const double length =
        fixed ? furnace_roulette_mean_rays(f.roulette.min_depth, f.q[i]) : std::nan("");
    const auto known = [](double x) { return std::isfinite(x) ? Cell(x) : Cell(); };
    table.add_row({fixed ? "fixed" : "throughput", fixed ? Cell(f.q[i]) : Cell(), r.radiance.mean(),
                   r.radiance.variance(), known(var), r.rays.mean(), known(length), r.seconds,
                   efficiency(r), known(1.0 / (var * length * seconds_per_ray)),
                   fixed && i == best ? 1 : 0});
  }
  return table;
}

// path_length.csv: how many of the paths at --fixed-q traced r rays, against the geometric law
// P(R = r) = q^(r - d - 1) (1 - q), r >= d + 1. Rows stop where the law's tail falls below 1e-4.
inline Table path_length_study(const Furnace& f, PathStats& stats) {
  const Roulette& r = f.roulette;
  const Roulette fixed{r.min_depth, RoulettePolicy::fixed, r.q, r.floor};
  const std::vector<FurnacePath> paths = f.trace(k_length_block, f.with_roulette(fixed));
  const int longest = r.min_depth + 1 + static_cast<int>(std::ceil(std::log(1e-4) / std::log(r.q)));
  std::vector<std::uint64_t> count(static_cast<std::size_t>(longest) + 1, 0);
  for (const FurnacePath& path : paths) {
    stats.radiance.add(path.radiance);
    stats.rays.add(static_cast<double>(path.rays));
    if (path.rays <= static_cast<std::uint64_t>(longest)) ++count[path.rays];
  }
  Table table({{"rays", Column::integer},
               {"paths", Column::integer},
               {"fraction", Column::real},
               {"probability", Column::real},
               {"expected", Column::real, 6}});
  for (int rays = 1; rays <= longest; ++rays) {
    const double p = furnace_roulette_length_probability(r.min_depth, r.q, rays);
    const auto n = count[static_cast<std::size_t>(rays)];
    table.add_row({rays, n, static_cast<double>(n) / f.paths, p, p * f.paths});
  }
  return table;
}

}  // namespace mcrt
