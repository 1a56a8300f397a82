#pragma once
// What a1's checks ask of the student's estimators, with everything a request carries: seeds
// and streams in place of an Rng, integrands named by an A1Integrand. A1Producer runs them with
// the functions it holds (LocalSubject: the student's; diagnosis_test.cpp: a known-wrong one).
// No test and no verdict here: the subject program includes it.

#include <array>
#include <cstdint>
#include <vector>

#include "assignments/subject/requests.hpp"
#include "core/rng.hpp"
#include "integration/domain.hpp"
#include "integration/integrands.hpp"

namespace mcrt::testing::assignment {

/// Runs body(f) with the integrand `kind` names (`param`: the constant's value).
template <class Body>
auto with_a1_integrand(A1Integrand kind, double param, Body&& body) {
  switch (kind) {
    case A1Integrand::gaussian: return body(Gaussian1D{});
    case A1Integrand::line: return body([](double x) { return 3.0 * x + 1.0; });
    case A1Integrand::square: return body([](double x) { return x * x; });
    case A1Integrand::constant: break;
  }
  return body([param](double) { return param; });
}

/// disk(n, rng), ball(k, n, rng), count(k, n, rng), basic(f, segment, n, rng) -> estimate with
/// standard_error, rule(f, segment, n): a1.1 to a1.4's functions.
template <class Disk, class Ball, class Count, class Basic, class Rule>
struct A1Producer {
  Disk disk;
  Ball ball;
  Count count;
  Basic basic;
  Rule rule;

  double a1_disk(std::uint64_t n, std::uint64_t seed, std::uint64_t stream) const {
    Rng rng(seed, stream);
    return disk(n, rng);
  }
  double a1_ball(int k, std::uint64_t n, std::uint64_t seed, std::uint64_t stream) const {
    Rng rng(seed, stream);
    return ball(k, n, rng);
  }
  /// count_in_ball for each (k, n) in turn, all from one Rng(seed, stream).
  std::vector<std::uint64_t> a1_ball_counts(const std::vector<std::array<std::uint64_t, 2>>& calls,
                                            std::uint64_t seed, std::uint64_t stream) const {
    Rng rng(seed, stream);
    std::vector<std::uint64_t> out;
    for (const auto& [k, n] : calls) out.push_back(count(static_cast<int>(k), n, rng));
    return out;
  }
  EstimateAndError a1_monte_carlo(A1Integrand f, double param, Segment s, std::uint64_t n,
                                  std::uint64_t seed, std::uint64_t stream) const {
    Rng rng(seed, stream);
    return with_a1_integrand(f, param, [&](const auto& g) {
      const auto e = basic(g, s, n, rng);
      return EstimateAndError{e.estimate, e.standard_error};
    });
  }
  double a1_trapezoid(A1Integrand f, double param, Segment s, std::uint64_t n) const {
    return with_a1_integrand(f, param,
                             [&](const auto& g) { return static_cast<double>(rule(g, s, n)); });
  }
};

template <class Disk, class Ball, class Count, class Basic, class Rule>
A1Producer<Disk, Ball, Count, Basic, Rule> a1_producer(Disk disk, Ball ball, Count count,
                                                       Basic basic, Rule rule) {
  return {disk, ball, count, basic, rule};
}

}  // namespace mcrt::testing::assignment
