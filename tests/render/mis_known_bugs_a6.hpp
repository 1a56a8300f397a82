#pragma once
// The known-wrong variants of a6 (glossy lobe, heuristics, MIS on Veach's plates), each an a6
// solution but for one line, and the producer that plugs them in where a6's checks expect the
// student's functions. tests/assignments/diagnosis_test.cpp shows each one's diagnosis;
// tests/assignment_fairness/ measures their detection. Never in a kit (scripts/make-assignment
// EXCLUDED): a6 is the last assignment, so every kit stubs what these are one line off.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "assignments/a6/a6_checks.hpp"
#include "assignments/a6/a6_produce.hpp"
#include "core/math.hpp"
#include "render/glossy_direct.hpp"
#include "render/mis.hpp"
#include "sampling/phong.hpp"

namespace mcrt::testing::assignment {

/// The student's a6 functions, any of them replaced.
inline Vec3 student_lobe(Vec2 u, double m) { return sample_phong_lobe_local(u, m); }
inline double student_lobe_pdf(const Vec3& w, const Vec3& r, double m) {
  return phong_lobe_pdf(w, r, m);
}
inline double student_weight(A6Heuristic h, double p_s, double p_o) {
  return h == A6Heuristic::power ? power_heuristic(p_s, p_o) : balance_heuristic(p_s, p_o);
}
inline double student_mis(const VeachPlates& scene, const Hit& hit, const Vec3& wo, MisHeuristic h,
                          Rng& rng, RayCount& count) {
  return estimate_mis(scene, hit, wo, h, rng, count);
}

template <class Lobe = decltype(&student_lobe), class Pdf = decltype(&student_lobe_pdf),
          class Weight = decltype(&student_weight), class Mis = decltype(&student_mis)>
struct A6Variant {
  Lobe lobe = &student_lobe;
  Pdf pdf = &student_lobe_pdf;
  Weight weight = &student_weight;
  Mis mis = &student_mis;
  std::vector<Vec3> a6_lobe_samples(double m, const std::vector<Vec2>& u) const {
    std::vector<Vec3> out;
    for (const Vec2& x : u) out.push_back(lobe(x, m));
    return out;
  }
  std::vector<double> a6_lobe_pdf(double m, Vec3 r, const std::vector<Vec3>& points) const {
    std::vector<double> out;
    for (const Vec3& w : points) out.push_back(pdf(w, r, m));
    return out;
  }
  std::vector<double> a6_weights(A6Heuristic h, const std::vector<Vec2>& pairs) const {
    std::vector<double> out;
    for (const Vec2& p : pairs) out.push_back(weight(h, p.x, p.y));
    return out;
  }
  std::vector<double> a6_regions(A6Strategy s, int width, int height, int spp,
                                 std::uint64_t seed) const {
    return a6_region_samples(mis, s, width, height, spp, seed);
  }
};
template <class L>
A6Variant<L> with_lobe(L l) {
  return {l};
}
template <class P>
A6Variant<decltype(&student_lobe), P> with_lobe_pdf(P p) {
  return {&student_lobe, p};
}
template <class W>
A6Variant<decltype(&student_lobe), decltype(&student_lobe_pdf), W> with_weight(W w) {
  return {&student_lobe, &student_lobe_pdf, w};
}
template <class M>
A6Variant<decltype(&student_lobe), decltype(&student_lobe_pdf), decltype(&student_weight), M>
with_mis(M m) {
  return {&student_lobe, &student_lobe_pdf, &student_weight, m};
}

/// The lobe's direction from cos(alpha) = c and phi = 2 pi u1 (sin from (1 - c)(1 + c)).
inline Vec3 lobe_direction(double c, double phi) {
  const double s = std::sqrt((1.0 - c) * (1.0 + c));
  return {s * std::cos(phi), s * std::sin(phi), c};
}

// ---- a6.1 the lobe
/// cos(alpha) = u^(1/m): the CDF of the lobe's c^m, not of its density (m + 1) c^m.
inline Vec3 lobe_cosine_to_one_over_m(Vec2 u, double m) {
  return lobe_direction(std::pow(u.x, 1.0 / m), k_two_pi * u.y);
}
/// phi = pi u1: half the azimuths.
inline Vec3 lobe_half_the_azimuths(Vec2 u, double m) {
  return lobe_direction(std::pow(u.x, 1.0 / (m + 1.0)), k_pi * u.y);
}
/// sin(alpha) = sqrt(1 - c^2): right in distribution, but its digits cancel for a sharp lobe.
inline Vec3 lobe_sine_from_one_minus_cos_squared(Vec2 u, double m) {
  const double c = std::pow(u.x, 1.0 / (m + 1.0)), s = std::sqrt(std::max(0.0, 1.0 - c * c));
  return {s * std::cos(k_two_pi * u.y), s * std::sin(k_two_pi * u.y), c};
}
/// The pdf with the BRDF's normalisation (m + 2) / 2 pi, not the lobe's (m + 1) / 2 pi.
inline double lobe_pdf_with_the_brdfs_normalisation(const Vec3& w, const Vec3& r, double m) {
  return (m + 2.0) / (m + 1.0) * phong_lobe_pdf(w, r, m);
}
/// The pdf round the normal (w.z), not round the mirror direction r.
inline double lobe_pdf_round_the_normal(const Vec3& w, const Vec3&, double m) {
  return phong_lobe_pdf(w, Vec3(0.0, 0.0, 1.0), m);
}

// ---- a6.2 the heuristics
/// The power heuristic that returns the balance heuristic's weight.
inline double power_heuristic_not_squared(A6Heuristic, double p_s, double p_o) {
  return balance_heuristic(p_s, p_o);
}
/// p_s / (p_s + p_o) with no guard for 0 / 0.
inline double heuristic_without_the_guard(A6Heuristic, double p_s, double p_o) {
  return p_s / (p_s + p_o);
}
/// p_s^2 / (p_s + p_o): the numerator squared, the denominator not.
inline double weights_that_do_not_sum_to_one(A6Heuristic, double p_s, double p_o) {
  return p_s + p_o > 0.0 ? p_s * p_s / (p_s + p_o) : 0.0;
}

// ---- a6.3 MIS on the plates
/// MIS with the weights (w_l, w_b) that `weights(heuristic, light, bsdf)` gives.
template <class Weights>
auto mis_weighted_by(Weights weights) {
  return [weights](const VeachPlates& scene, const Hit& hit, const Vec3& wo, MisHeuristic h,
                   Rng& rng, RayCount& count) {
    const GlossySample l = draw_light_sample(scene, hit, wo, rng, count);
    const GlossySample b = draw_bsdf_sample(scene, hit, wo, rng, count);
    const auto [w_l, w_b] = weights(h, l, b);
    return w_l * sample_value(l.f_le_cos, l.pdf_light) + w_b * sample_value(b.f_le_cos, b.pdf_bsdf);
  };
}
/// The BSDF sample weighted as if it were the light sample: w(p_l, p_b) for both.
inline auto mis_bsdf_hit_weighted_as_if_by_nee() {
  return mis_weighted_by([](MisHeuristic h, const GlossySample& l, const GlossySample& b) {
    return std::pair{mis_weight(h, l.pdf_light, l.pdf_bsdf),
                     mis_weight(h, b.pdf_light, b.pdf_bsdf)};
  });
}
/// The BSDF sample that hits a light added with weight 1.
inline auto mis_bsdf_hit_not_weighted() {
  return mis_weighted_by([](MisHeuristic h, const GlossySample& l, const GlossySample&) {
    return std::pair{mis_weight(h, l.pdf_light, l.pdf_bsdf), 1.0};
  });
}
/// The light sample added with weight 1.
inline auto mis_light_sample_not_weighted() {
  return mis_weighted_by([](MisHeuristic h, const GlossySample&, const GlossySample& b) {
    return std::pair{1.0, mis_weight(h, b.pdf_bsdf, b.pdf_light)};
  });
}
/// Light sampling alone, weights 1 and 0: unbiased, but no better than light sampling.
inline auto mis_light_sampling_passed_off() {
  return mis_weighted_by([](MisHeuristic, const GlossySample&, const GlossySample&) {
    return std::pair{1.0, 0.0};
  });
}
/// draw_light_sample with p_l = p_A / N (sample_sphere_cone's area pdf), not per steradian.
inline double mis_light_pdf_per_unit_area(const VeachPlates& scene, const Hit& hit, const Vec3& wo,
                                          MisHeuristic h, Rng& rng, RayCount& count) {
  const Phong& material = scene.materials[hit.material];
  const std::size_t j = rng.uniform_below(static_cast<std::uint32_t>(scene.light_count()));
  const LightPoint y =
      sample_sphere_cone(scene.lights[j].center, scene.lights[j].radius, hit.point, rng.uniform2());
  const Vec3 w = glm::normalize(y.point - hit.point);
  GlossySample l;
  l.pdf_light = y.pdf_area / static_cast<double>(scene.light_count());
  l.pdf_bsdf = phong_pdf(material, w, hit.normal, wo);
  l.f_le_cos = phong_brdf(material, w, wo, hit.normal) *
               traced_emission(scene, spawn_ray(hit, w), count) *
               std::max(0.0, glm::dot(w, hit.normal));
  const GlossySample b = draw_bsdf_sample(scene, hit, wo, rng, count);
  return mis_weight(h, l.pdf_light, l.pdf_bsdf) * sample_value(l.f_le_cos, l.pdf_light) +
         mis_weight(h, b.pdf_bsdf, b.pdf_light) * sample_value(b.f_le_cos, b.pdf_bsdf);
}

/// The known-wrong producer a6's efficiency test must fail: light sampling passed off as MIS.
inline auto light_sampling_as_mis() { return with_mis(mis_light_sampling_passed_off()); }

}  // namespace mcrt::testing::assignment
