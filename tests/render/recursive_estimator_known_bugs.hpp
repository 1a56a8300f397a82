#pragma once
// Known-wrong furnace moments of the recursive N^k estimator: what a wrong estimator would
// converge to, kept so the tests can show the furnace checks (render/recursive_estimator_furnace.hpp)
// reject them (tests/render/recursive_estimator_test.cpp).

#include "render/recursive_estimator.hpp"

namespace mcrt::testing {

/// Wrong: one bounce too few, depth k - 1 (at a = 0.5, N = 2, k = 3: mean 1.75, not 1.875).
inline FurnaceMoments furnace_moments_one_bounce_short(double albedo, int branching, int depth) {
  return furnace_moments(albedo, branching, depth - 1);
}

/// Wrong: an albedo 2% too high, e.g. a BRDF of 1.02 a / pi.
inline FurnaceMoments furnace_moments_albedo_two_percent_high(double albedo, int branching,
                                                              int depth) {
  return furnace_moments(1.02 * albedo, branching, depth);
}

/// Wrong: the N branches reuse one direction, so branching reduces no variance: that of N = 1.
inline FurnaceMoments furnace_moments_one_shared_branch(double albedo, int, int depth) {
  return furnace_moments(albedo, 1, depth);
}

/// Wrong: a variance 10% high.
inline FurnaceMoments furnace_moments_variance_ten_percent_high(double albedo, int branching,
                                                                int depth) {
  FurnaceMoments m = furnace_moments(albedo, branching, depth);
  m.variance *= 1.1;
  return m;
}

}  // namespace mcrt::testing
