#pragma once
// The hidden tests that are statistical, as single-seed p-values for the fairness measurement
// (tests/assignment_fairness/). Each hidden test computes its p-value inline, at one fixed
// seed, and fails below 1e-6; this file repeats that computation at any seed and at any of the
// parameters a course variant may draw (tests/assignments/answers/key.py, HIDDEN), and must
// change when the test does. It stays in the instructor tree: no kit or autograder holds this
// folder but for the hidden test it grades.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assignment_fairness/measured_check.hpp"
#include "assignments/a4/a4_checks.hpp"
#include "assignments/a5/a5_checks.hpp"
#include "assignments/a6/a6_checks.hpp"

namespace mcrt::testing::assignment {

/// The hidden tests' level: one seed, p below 1e-6 fails.
inline constexpr double k_hidden_alpha = 1e-6;

/// The defaults of the hidden tests' varied parameters (the k_hidden_* lines without --variant).
inline constexpr double k_hidden_a4_albedo = 0.8;
inline constexpr double k_hidden_a5_roulette_q = 0.9;
inline constexpr double k_hidden_a5_roulette_albedo = 0.6;

/// a4_hidden_test.cpp, FurnaceMeanAtAnotherAlbedo: 20000 paths at depth 5 (block 3) of
/// `furnace` (a4_checks.hpp's furnace producers) at `albedo`, their mean against the closed form.
template <class Furnace>
double a4_hidden_furnace_p_value(Furnace&& furnace, double albedo, std::uint64_t seed) {
  RunningStats r;
  for (double x : furnace(albedo, 5, 20000, seed, 3)) r.add(x);
  return z_test_p_value(r.mean(), furnace_radiance(albedo, 1.0, 5),
                        std::sqrt(furnace_radiance_variance(albedo, 1.0, 5) / 20000.0));
}

/// a5_hidden_test.cpp, RouletteFromVertexZero: 20000 paths (block 5) of `s`'s roulette with
/// a fixed q from vertex 0, their mean against the untruncated furnace.
template <class S>
double a5_hidden_roulette_p_value(S& s, double q, double albedo, std::uint64_t seed) {
  const Roulette roulette{0, RoulettePolicy::fixed, q, 0.05};
  RunningStats L;
  for (const FurnacePath& p : s.a5_paths(roulette_estimator(roulette), albedo, 20000, seed, 5))
    L.add(p.radiance);
  return z_test_p_value(L.mean(), furnace_radiance_untruncated(albedo, 1.0),
                        std::sqrt(furnace_roulette_variance(albedo, 1.0, 0, q) / 20000.0));
}

/// What a variant may draw for the two statistical hidden tests (key.py's HIDDEN choices).
struct HiddenGrid {
  std::vector<double> a4_albedo;
  std::vector<double> a5_roulette_q, a5_roulette_albedo;
  std::size_t a5_points() const { return a5_roulette_q.size() * a5_roulette_albedo.size(); }
};

/// Seed `seed`'s point of a grid of `points`: consecutive seeds go round the grid, so a run of
/// n x points seeds measures every point at n seeds.
inline std::size_t grid_point(std::uint64_t seed, std::size_t points) {
  return static_cast<std::size_t>(seed % points);
}

template <class S>
std::vector<MeasuredCheck> hidden_statistical_checks(S& s) {
  return {
      {"a4_hidden_furnace", "a4-hidden.A4Hidden.FurnaceMeanAtAnotherAlbedo", k_hidden_alpha, false,
       false,
       [&s](std::uint64_t seed) {
         return a4_hidden_furnace_p_value(furnace_of_subject(s), k_hidden_a4_albedo, seed);
       }},
      {"a5_hidden_roulette", "a5-hidden.A5Hidden.RouletteFromVertexZero", k_hidden_alpha, false,
       false,
       [&s](std::uint64_t seed) {
         return a5_hidden_roulette_p_value(s, k_hidden_a5_roulette_q, k_hidden_a5_roulette_albedo,
                                           seed);
       }},
      // a6_hidden_test.cpp, LobeAtMThreeFollowsItsPdf: a6.1's chi-square at m = 3, graded as the
      // public one (two of three seeds below 5e-4)
      {"a6_hidden_lobe_m3", "a6-hidden.A6Hidden.LobeAtMThreeFollowsItsPdf", k_seed_alpha, true,
       false,
       [&s,
        probability = bulk_cell_probabilities(lobe_pdf_of(s, 3.0), sampler_hemisphere_binning())](
           std::uint64_t seed) {
         return chi_square_points_test(lobe_samples_at(s, 3.0, seed), probability,
                                       sampler_hemisphere_binning())
             .p_value;
       }},
  };
}

/// The same two statistical hidden tests at every parameter a variant may draw: seed n is
/// measured at grid point grid_point(n, points). On the solution (`s`) these rows must be as
/// uniform as the defaults' are.
template <class S>
std::vector<MeasuredCheck> hidden_variant_checks(S& s, const HiddenGrid& grid) {
  std::vector<MeasuredCheck> checks;
  if (!grid.a4_albedo.empty())
    checks.push_back({"a4_hidden_furnace_variants", "a4-hidden.A4Hidden.FurnaceMeanAtAnotherAlbedo",
                      k_hidden_alpha, false, false, [&s, grid](std::uint64_t seed) {
                        const double a = grid.a4_albedo[grid_point(seed, grid.a4_albedo.size())];
                        return a4_hidden_furnace_p_value(furnace_of_subject(s), a, seed);
                      }});
  if (grid.a5_points() > 0)
    checks.push_back(
        {"a5_hidden_roulette_variants", "a5-hidden.A5Hidden.RouletteFromVertexZero", k_hidden_alpha,
         false, false, [&s, grid](std::uint64_t seed) {
           const std::size_t i = grid_point(seed, grid.a5_points());
           return a5_hidden_roulette_p_value(s, grid.a5_roulette_q[i % grid.a5_roulette_q.size()],
                                             grid.a5_roulette_albedo[i / grid.a5_roulette_q.size()],
                                             seed);
         }});
  return checks;
}

/// The number of points of the variant row `name`'s grid (0: not a variant row).
inline std::size_t variant_points(const std::string& name, const HiddenGrid& grid) {
  if (name == "a4_hidden_furnace_variants") return grid.a4_albedo.size();
  if (name == "a5_hidden_roulette_variants") return grid.a5_points();
  return 0;
}

}  // namespace mcrt::testing::assignment
