#pragma once
// Producers of the assignment checks with one of the student's functions replaced by a
// known-wrong variant: what tests/assignments/diagnosis_test.cpp grades to show each diagnosis
// names its bug, and tests/assignment_fairness/ measures the detection of. The variants
// themselves are in tests/<layer>/*_known_bugs.hpp; this file only plugs them in where a check expects the
// student's function.

#include <cstdint>

#include "assignments/a1/a1_produce.hpp"
#include "assignments/a5/a5_produce.hpp"
#include "core/rng.hpp"
#include "integration/disk_area.hpp"
#include "integration/domain.hpp"
#include "integration/monte_carlo.hpp"
#include "integration/quadrature.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/next_event_estimation.hpp"
#include "render/russian_roulette.hpp"

namespace mcrt::testing::assignment {

/// a1's functions as LocalSubject calls them.
inline auto student_disk() {
  return [](std::uint64_t n, Rng& rng) { return estimate_disk_area(n, rng); };
}
inline auto student_ball() {
  return [](int k, std::uint64_t n, Rng& rng) { return estimate_ball_volume(k, n, rng); };
}
inline auto student_count() {
  return [](int k, std::uint64_t n, Rng& rng) { return count_in_ball(k, n, rng); };
}
inline auto student_basic() {
  return [](const auto& f, const Segment& s, std::uint64_t n, Rng& rng) {
    return monte_carlo(f, s, n, rng);
  };
}
inline auto student_rule() {
  return [](const auto& f, const Segment& s, std::uint64_t n) { return trapezoid(f, s, n); };
}

/// a1's producer with the student's functions but one replaced.
template <class D>
auto with_disk(D d) {
  return a1_producer(d, student_ball(), student_count(), student_basic(), student_rule());
}
template <class B>
auto with_ball(B b) {
  return a1_producer(student_disk(), b, student_count(), student_basic(), student_rule());
}
template <class B>
auto with_basic(B b) {
  return a1_producer(student_disk(), student_ball(), student_count(), b, student_rule());
}
template <class R>
auto with_rule(R r) {
  return a1_producer(student_disk(), student_ball(), student_count(), student_basic(), r);
}

/// a5's producer with one of the student's three estimators replaced.
template <class R>
auto with_roulette(R roulette) {
  return a5_producer(roulette, estimate_importance_path_radiance, estimate_nee_radiance);
}

template <class I>
auto with_importance(I importance) {
  return a5_producer(estimate_path_radiance_roulette, importance, estimate_nee_radiance);
}

template <class N>
auto with_nee(N nee) {
  return a5_producer(estimate_path_radiance_roulette, estimate_importance_path_radiance, nee);
}

/// A known-wrong path tracer as a5.2's estimator: it ignores the pdf it is handed.
template <class Tracer>
auto ignoring_the_pdf(Tracer tracer) {
  return [tracer](const Scene& scene, Ray ray, int max_depth, const HemispherePdf&, Rng& rng,
                  RayCount& count) { return tracer(scene, ray, max_depth, rng, count); };
}

/// A known-wrong NEE as a5.3's estimator: its depth cut taken from the PathEnd.
template <class Nee>
auto with_path_end(Nee nee) {
  return [nee](const Scene& scene, Ray ray, const PathEnd& end, Rng& rng, RayCount& count) {
    return nee(scene, ray, end.max_depth, rng, count);
  };
}

}  // namespace mcrt::testing::assignment
