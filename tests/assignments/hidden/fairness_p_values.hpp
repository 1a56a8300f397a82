#pragma once
// The hidden tests that are statistical, as single-seed p-values for the fairness measurement
// (tests/assignment_fairness/). Each hidden test computes its p-value inline, at one fixed
// seed, and fails below 1e-6; this file repeats that computation at any seed, and must change
// when the test does. It stays in the instructor tree: no kit or autograder holds this folder
// but for the hidden test it grades.

#include <cmath>
#include <cstdint>
#include <vector>

#include "assignment_fairness/measured_check.hpp"
#include "assignments/a4/a4_checks.hpp"
#include "assignments/a5/a5_checks.hpp"

namespace mcrt::testing::assignment {

/// The hidden tests' level: one seed, p below 1e-6 fails.
inline constexpr double k_hidden_alpha = 1e-6;

template <class S>
std::vector<MeasuredCheck> hidden_statistical_checks(S& s) {
  return {
      // a4_hidden_test.cpp, FurnaceMeanAtAnotherAlbedo at its default k_hidden_* values (seed 4242)
      {"a4_hidden_furnace", "a4-hidden.A4Hidden.FurnaceMeanAtAnotherAlbedo", k_hidden_alpha, false, false,
       [&s](std::uint64_t seed) {
         RunningStats r;
         for (double x : s.path_furnace(0.8, 5, 20000, seed, 3)) r.add(x);
         return z_test_p_value(r.mean(), furnace_radiance(0.8, 1.0, 5),
                               std::sqrt(furnace_radiance_variance(0.8, 1.0, 5) / 20000.0));
       }},
      // a5_hidden_test.cpp, RouletteFromVertexZero at its default k_hidden_* values (seed 4243)
      {"a5_hidden_roulette", "a5-hidden.A5Hidden.RouletteFromVertexZero", k_hidden_alpha, false, false,
       [&s](std::uint64_t seed) {
         const Roulette roulette{0, RoulettePolicy::fixed, 0.9, 0.05};
         RunningStats L;
         for (const FurnacePath& p : s.a5_paths(roulette_estimator(roulette), 0.6, 20000, seed, 5)) L.add(p.radiance);
         return z_test_p_value(L.mean(), furnace_radiance_untruncated(0.6, 1.0),
                               std::sqrt(furnace_roulette_variance(0.6, 1.0, 0, 0.9) / 20000.0));
       }},
  };
}

}  // namespace mcrt::testing::assignment
