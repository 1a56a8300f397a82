#pragma once
// Russian-roulette paths in the furnace, and the tests run on them, shared by the statistical
// checks (tests/render/russian_roulette_checks.cpp) and by the unit tests that show those
// checks reject the known-wrong variants of tests/render/russian_roulette_known_bugs.hpp.
//
// In the furnace (albedo a < 1, emission Le everywhere) roulette's radiance has the mean
// Le / (1 - a) in every direction, fixed q has the variance furnace_roulette_variance, and its
// paths trace R = d + 1 + M rays with M geometric (common/render/russian_roulette.hpp).

#include <cmath>
#include <cstdint>
#include <vector>

#include "integration/statistics.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "stats/chi_square.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing {

struct RouletteFurnaceSetup {
  double albedo = 0.5;
  double emission = 1.0;
  Roulette roulette;
};

/// The estimator under test, as roulette_furnace_paths takes it.
inline Color chapter_roulette(const Scene& scene, Ray ray, const Roulette& roulette, Rng& rng,
                              RayCount& count) {
  return estimate_path_radiance_roulette(scene, ray, roulette, rng, count);
}

/// n paths of `estimate(scene, ray, roulette, rng, count)` from the furnace's centre, path i
/// from stream (block, i) of `seed` (distinct blocks give independent sets).
template <class Estimator>
std::vector<FurnacePath> roulette_furnace_paths(const RouletteFurnaceSetup& setup, int n,
                                                std::uint64_t seed, std::uint64_t block,
                                                Estimator&& estimate) {
  const Scene scene = make_furnace(setup.albedo, setup.emission);
  return trace_furnace_paths(static_cast<std::uint64_t>(n), seed, block, 1,
                             [&](const Ray& ray, Rng& rng, RayCount& count) {
                               return estimate(scene, ray, setup.roulette, rng, count);
                             });
}

inline std::vector<double> radiance_values(const std::vector<FurnacePath>& paths) {
  std::vector<double> values;
  values.reserve(paths.size());
  for (const FurnacePath& path : paths) values.push_back(path.radiance);
  return values;
}

/// Two-sided test of the mean radiance against Le / (1 - a). For fixed q above 4a^2/3 the
/// standard error comes from the closed-form variance (a z-test); otherwise (the throughput
/// policy) from the sample variance, a t-test. Either way n is large enough for the central
/// limit theorem in the setups the checks use (they have a finite third moment at least).
inline double roulette_mean_p_value(const RouletteFurnaceSetup& setup,
                                    const std::vector<FurnacePath>& paths) {
  RunningStats radiance;
  for (const FurnacePath& path : paths) radiance.add(path.radiance);
  const double expected = furnace_radiance_untruncated(setup.albedo, setup.emission);
  const Roulette& r = setup.roulette;
  if (r.policy == RoulettePolicy::fixed &&
      r.q > furnace_roulette_variance_threshold(setup.albedo)) {
    const double variance =
        furnace_roulette_variance(setup.albedo, setup.emission, r.min_depth, r.q);
    return z_test_p_value(radiance.mean(), expected,
                          std::sqrt(variance / static_cast<double>(radiance.count())));
  }
  return t_test_p_value(radiance.mean(), radiance.variance(), radiance.count(), expected);
}

/// Chi-square test of the rays each path traced against the geometric law
/// P(R = r) = q^(r - d - 1) (1 - q), r >= d + 1: one cell per length r = 1..longest and one
/// for every longer path; a path shorter than d + 1 rays, where the law is 0, fails at once.
inline ChiSquareResult path_length_test(int min_depth, double q,
                                        const std::vector<FurnacePath>& paths) {
  const double n = static_cast<double>(paths.size());
  // Cells until the expected count of the tail falls below 5 (pooling joins the small ones).
  const int longest = min_depth + 1 + static_cast<int>(std::ceil(std::log(5.0 / n) / std::log(q)));
  std::vector<CellCount> cells(static_cast<std::size_t>(longest) + 1);
  for (int r = 1; r <= longest; ++r) {
    cells[static_cast<std::size_t>(r - 1)].u_index = r;
    cells[static_cast<std::size_t>(r - 1)].expected =
        n * furnace_roulette_length_probability(min_depth, q, r);
  }
  CellCount& tail = cells.back();  // R > longest: P = q^(longest - d)
  tail.u_index = longest + 1;
  tail.expected = n * std::pow(q, longest - min_depth);
  for (const FurnacePath& path : paths) {
    const auto r = static_cast<int>(
        std::min<std::uint64_t>(path.rays, static_cast<std::uint64_t>(longest) + 1));
    cells[static_cast<std::size_t>(r - 1)].observed += 1.0;
  }
  return chi_square_test(std::move(cells), 0);
}

}  // namespace mcrt::testing
