#pragma once
// The grading procedures of a6.4, the dielectric's sampling (sample_dielectric). Each judges
// what a producer returns (a Subject, or a known-wrong variant in diagnosis_test.cpp) through
// its a6_dielectric request: the sample at each (wo, n, entering, u) for glass of one index.
//   - the furnace: a glass ball in a uniform environment of radiance L is invisible, every
//     path returns L exactly (R + T = 1, nothing absorbed), grazing rays included, at indices
//     above 1 and below it (a bubble, where light arriving from outside can be reflected whole);
//   - the branch: at a few incident angles on either side, every sample is the mirror
//     direction or Snell's (unit, weight 1), never a refraction past the critical angle, and
//     the fraction that reflects is the Fresnel reflectance R: a chi-square of the counts,
//     three seeds, majority of 2 rejections at 5e-4 (grading.hpp).
// The expected values come from render/fresnel.hpp (every kit holds it: the physics, not the
// sampling).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/grading.hpp"
#include "assignments/subject/requests.hpp"
#include "core/rng.hpp"
#include "geometry/sphere.hpp"
#include "render/fresnel.hpp"
#include "sampling/frame.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

/// A direction is unit, or the mirror or Snell direction, within this: the solution's are
/// exact to a few ulps (1e-15); another exact formula's round-off stays far below 1e-9, and
/// every bug below moves a direction or a length by more than 1e-3.
inline constexpr double k_a6_direction_tolerance = 1e-9;
/// A weight is 1 within this: R / R is exactly 1 in floating point, R * (1 / R) within 2 ulps
/// (4.4e-16); any absorption a student could write is many orders larger.
inline constexpr double k_a6_weight_tolerance = 1e-14;

/// What one sample at a hit was asked and what the checks expect of it.
struct DielectricExpectation {
  double cos_i = 0.0;
  double eta = 1.0;          ///< eta_i / eta_t for the side wo is on
  double reflectance = 1.0;  ///< R (1 where no refracted direction exists)
  Vec3 mirror;
  std::optional<Vec3> snell;  ///< none past the critical angle
};

inline DielectricExpectation expect_dielectric(double ior, const DielectricQuery& q) {
  DielectricExpectation e;
  const double eta_i = q.entering ? 1.0 : ior, eta_t = q.entering ? ior : 1.0;
  e.eta = eta_i / eta_t;
  e.cos_i = glm::dot(q.wo, q.n);
  e.mirror = reflect(q.wo, q.n);
  e.reflectance = fresnel_dielectric(e.cos_i, eta_i, eta_t);
  if (const std::optional<double> cos_t = refracted_cosine(e.cos_i, e.eta))
    e.snell = refract(q.wo, q.n, e.cos_i, *cos_t, e.eta);
  return e;
}

inline bool same_direction(const Vec3& a, const Vec3& b) {
  return glm::length(a - b) <= k_a6_direction_tolerance;
}

inline std::string dielectric_where(double ior, const DielectricQuery& q,
                                    const DielectricExpectation& e) {
  return fmt::format("{} glass of n = {} at cos(theta_i) = {:.6g}",
                     q.entering ? "entering" : "leaving", ior, e.cos_i);
}

/// "" when the answer is a valid sample (the mirror or Snell direction, unit, weight 1, the
/// flag right), else a diagnosis naming what is wrong; `reflected` says which branch it took.
inline std::string judge_dielectric_sample(double ior, const DielectricQuery& q,
                                           const DielectricAnswer& a, bool& reflected) {
  const DielectricExpectation e = expect_dielectric(ior, q);
  const std::string where = dielectric_where(ior, q, e);
  const bool finite = std::isfinite(a.wi.x) && std::isfinite(a.wi.y) && std::isfinite(a.wi.z);
  if (!finite) {
    if (!e.snell)
      return diagnosis(fmt::format(
          "your direction is NaN {}, past the critical angle: there eta sin(theta_i) > 1, no refracted direction "
          "exists (1 - sin^2(theta_t) < 0) and all the light is reflected (total internal reflection)",
          where));
    return diagnosis(fmt::format("your direction is NaN or infinite {}", where));
  }
  const double length = glm::length(a.wi);
  if (std::abs(length - 1.0) > k_a6_direction_tolerance) {
    const Vec3 unit = a.wi / length;
    if (e.snell && same_direction(unit, *e.snell))
      return diagnosis(fmt::format(
          "your refracted direction has length {:.6f}, not 1, {}: it points the right way; "
          "normalise it (a ray's direction must be unit: intersections assume |d| = 1)",
          length, where));
    if (same_direction(unit, e.mirror))
      return diagnosis(
          fmt::format("your reflected direction has length {:.6f}, not 1, {}", length, where));
    return diagnosis(fmt::format("your direction has length {:.6f}, not 1, {}", length, where));
  }
  const bool is_mirror = same_direction(a.wi, e.mirror),
             is_snell = e.snell && same_direction(a.wi, *e.snell);
  if (!is_mirror && !is_snell) {
    if (!q.entering) {  // leaving with the ratio of entering, 1/n: n not inverted
      if (const std::optional<double> cos_t = refracted_cosine(e.cos_i, 1.0 / ior);
          cos_t && same_direction(a.wi, refract(q.wo, q.n, e.cos_i, *cos_t, 1.0 / ior)))
        return diagnosis(fmt::format(
            "leaving the glass your refracted direction uses eta = 1/n, the ratio of entering ({}): leaving, light "
            "goes from glass into air, eta_i = n, eta_t = 1: invert the ratio when `entering` is false",
            where));
    }
    if (!e.snell && glm::dot(a.wi, q.n) < 0.0)
      return diagnosis(fmt::format(
          "your path refracts {}, past the critical angle: no refracted direction exists "
          "there, all the light is reflected (total internal reflection)",
          where));
    return diagnosis(fmt::format(
        "your direction is neither the mirror direction of wo nor Snell's refracted one {}",
        where));
  }
  for (double w : {a.weight.x, a.weight.y, a.weight.z})
    if (!(std::abs(w - 1.0) <= k_a6_weight_tolerance)) {
      const double r = e.reflectance;
      const bool fresnel_factor = std::abs(w - r) < 1e-9 || std::abs(w - (1.0 - r)) < 1e-9;
      return diagnosis(fmt::format(
          "your weight is {:.6g}, not the tint (1 here), {}{}", w, where,
          fresnel_factor
              ? ": it is R or 1 - R, but the branch is already chosen with that probability, so the "
                "Fresnel factor and the probability cancel (f cos / p = tint)"
              : ""));
    }
  if (a.transmitted != is_snell)
    return diagnosis(fmt::format("your sample's `transmitted` is {} for a {} direction {}",
                                 a.transmitted, is_snell ? "refracted" : "reflected", where));
  reflected = is_mirror;
  return "";
}

// ---------------------------------------------------------------- the furnace

/// The furnace's glass: indices above 1 (water, glass, diamond) and below (a bubble of 0.75,
/// where light from outside meets total internal reflection at grazing angles).
inline constexpr std::array<double, 4> k_a6_furnace_indices{1.333, 1.5, 2.42, 0.75};
/// Paths per index: impact parameters from the centre to grazing (the last three within 1e-3,
/// 1e-6 and 1e-9 of the rim), in random directions.
inline constexpr int k_a6_furnace_paths = 400;
/// A path inside the ball at a grazing angle reflects with R near 1 at every inner hit (R is
/// reciprocal): it may stay long. After this many bounces it stops, its weight so far checked.
inline constexpr int k_a6_furnace_bounces = 256;
inline constexpr double k_a6_environment = 1.0;  ///< the environment's radiance L
/// A path's radiance is L within this: at most k_a6_furnace_bounces weights, each within 2 ulps.
inline constexpr double k_a6_furnace_tolerance = 1e-12;
inline constexpr std::uint64_t k_a6_furnace_stream = 4100;

/// The first ray of furnace path i of `paths`: from 3 radii away, at impact parameter b.
inline Ray a6_furnace_ray(int i, int paths, Rng& rng) {
  const double b = i == paths - 1   ? 1.0 - 1e-9
                   : i == paths - 2 ? 1.0 - 1e-6
                   : i == paths - 3 ? 1.0 - 1e-3
                                    : std::sqrt((i + 0.5) / (paths - 3));
  const double z = 1.0 - 2.0 * rng.uniform(), phi = 2.0 * k_pi * rng.uniform();
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  const Vec3 d(s * std::cos(phi), s * std::sin(phi), z);
  const Frame frame(d);
  return {b * frame.tangent - 3.0 * d, d};
}

/// a6.4: a glass ball (radius 1) in a uniform environment of radiance L is invisible: every
/// path, traced with the subject's samples, returns L exactly, at every index of
/// k_a6_furnace_indices. Deterministic: u from Rng(k_grading_seeds[0], stream + path).
template <class S>
TaskResult check_dielectric_furnace(S&& subject) {
  const Sphere ball{Vec3(0.0), 1.0, 0};
  int met = 0, trapped = 0, total = 0;
  int max_bounces = 0;
  for (double ior : k_a6_furnace_indices) {
    struct Path {
      Ray ray;
      Vec3 throughput{1.0};
      int bounces = 0;
      Rng rng;
    };
    std::vector<Path> active;
    for (int i = 0; i < k_a6_furnace_paths; ++i) {
      Rng rng(k_grading_seeds[0], k_a6_furnace_stream + static_cast<std::uint64_t>(i));
      const Ray ray = a6_furnace_ray(i, k_a6_furnace_paths, rng);
      active.push_back({ray, Vec3(1.0), 0, rng});
    }
    total += k_a6_furnace_paths;
    while (!active.empty()) {
      std::vector<Path> next;
      std::vector<Hit> hits;
      std::vector<DielectricQuery> queries;
      for (Path& p : active) {
        const std::optional<Hit> hit = intersect(ball, p.ray, Interval{});
        if (!hit) {  // escaped: it sees the environment
          const Vec3 l = p.throughput * k_a6_environment;
          for (double c : {l.x, l.y, l.z})
            if (!(std::abs(c - k_a6_environment) <= k_a6_furnace_tolerance * k_a6_environment))
              return {
                  false,
                  fmt::format(
                      "glass furnace, n = {}: a path returned {:.17g}, not L = {}, after {} bounces",
                      ior, c, k_a6_environment, p.bounces)};
          met += p.bounces > 0;
          max_bounces = std::max(max_bounces, p.bounces);
          continue;
        }
        if (p.bounces == k_a6_furnace_bounces) {  // its weight so far was checked at every bounce
          ++trapped, ++met;
          continue;
        }
        hits.push_back(*hit);
        queries.push_back({-p.ray.direction, hit->normal, hit->front_face, p.rng.uniform()});
        next.push_back(p);
      }
      if (queries.empty()) break;
      const std::vector<DielectricAnswer> answers = subject.a6_dielectric(ior, queries);
      for (std::size_t k = 0; k < next.size(); ++k) {
        bool reflected = false;
        const std::string wrong = judge_dielectric_sample(ior, queries[k], answers[k], reflected);
        if (!wrong.empty())
          return {false,
                  fmt::format(
                      "glass furnace, n = {}: at bounce {} of a path the sample is not valid\n{}",
                      ior, next[k].bounces + 1, wrong)};
        next[k].throughput *= answers[k].weight;
        next[k].ray = spawn_ray(hits[k], answers[k].wi);
        ++next[k].bounces;
      }
      active = std::move(next);
    }
  }
  return {
      true,
      fmt::format(
          "glass furnace: {} paths at n = 1.333, 1.5, 2.42, 0.75, {} met the ball (up to {} bounces, "
          "{} stopped inside after {}): every one returned L = {} exactly",
          total, met, max_bounces, trapped, k_a6_furnace_bounces, k_a6_environment)};
}

// ---------------------------------------------------------------- the branch's frequency

/// An incident angle of the branch test: the index, the side wo is on, cos(theta_i).
struct DielectricCase {
  double ior;
  bool entering;
  double cos_i;
};
/// Entering and leaving, normal to grazing; n = 1.5's critical angle has cos 0.745 (0.76 is just
/// inside it, where R rises steeply; 0.5 past it), n = 2.42's has cos 0.9106.
inline constexpr std::array<DielectricCase, 9> k_a6_dielectric_cases{{
    {1.5, true, 1.0},
    {1.5, true, 0.5},
    {1.5, true, 0.05},
    {1.5, false, 0.9},
    {1.5, false, 0.76},
    {1.5, false, 0.5},
    {2.42, true, 0.3},
    {2.42, false, 0.95},
    {2.42, false, 0.6},
}};
/// Samples per case and seed: the reflected fraction's standard error is at most 0.0071, so
/// Fresnel with the ratio of entering when leaving (R 0.30 against 0.046 at cos 0.76) is 39
/// standard errors off, and reflecting with probability 1 - R (0.91 for 0.089, entering at cos
/// 0.5) more than 100. Every sample travels to the subject and back (8 + 7 numbers): 4x this
/// took 17 s of a grading at load 18, this about 4.
inline constexpr int k_a6_branch_samples = 5000;
inline constexpr std::uint64_t k_a6_branch_stream = 4200;

/// The queries of one case: wo at cos(theta_i) round a tilted normal, in a random azimuth.
inline std::vector<DielectricQuery> a6_branch_queries(const DielectricCase& c, std::uint64_t seed,
                                                      std::size_t index) {
  const Vec3 n = glm::normalize(Vec3(0.2, -0.3, 0.93));
  const Frame frame(n);
  const double sin_i = std::sqrt(std::max(0.0, 1.0 - c.cos_i * c.cos_i));
  Rng rng(seed, k_a6_branch_stream + index);
  std::vector<DielectricQuery> out(k_a6_branch_samples);
  for (DielectricQuery& q : out) {
    const double phi = 2.0 * k_pi * rng.uniform();
    q = {glm::normalize(frame.to_world({sin_i * std::cos(phi), sin_i * std::sin(phi), c.cos_i})), n,
         c.entering, rng.uniform()};
  }
  return out;
}

/// One case's count: the samples that reflected, and the R they should follow.
struct BranchCount {
  DielectricCase c;
  double reflectance = 1.0;
  int reflected = 0;
};

/// The chi-square p-value of the counts against reflectances `r(case)` (cases with R in (0, 1)).
template <class R>
double branch_p_value(const std::vector<BranchCount>& counts, R&& r, bool leaving_only = false) {
  double chi2 = 0.0;
  int dof = 0;
  for (const BranchCount& b : counts) {
    if (leaving_only && b.c.entering) continue;
    const double p = r(b), n = k_a6_branch_samples;
    if (p <= 0.0 || p >= 1.0) {
      if (b.reflected != (p >= 1.0 ? k_a6_branch_samples : 0)) return 0.0;
      continue;
    }
    chi2 += (b.reflected - n * p) * (b.reflected - n * p) / (n * p * (1.0 - p));
    ++dof;
  }
  return dof == 0 ? 1.0 : chi_square_upper_tail(chi2, dof);
}

/// What the counts say when they do not follow R.
inline std::string diagnose_branch_counts(const std::vector<BranchCount>& counts) {
  std::string table;
  for (const BranchCount& b : counts)
    table += fmt::format("\n  {} n = {} at cos(theta_i) = {}: reflected {:.4f} of {}, R = {:.4f}",
                         b.c.entering ? "entering" : "leaving ", b.c.ior, b.c.cos_i,
                         static_cast<double>(b.reflected) / k_a6_branch_samples,
                         k_a6_branch_samples, b.reflectance);
  const auto right = [](const BranchCount& b) { return b.reflectance; };
  // Fresnel from air into glass, whichever the side (past the critical angle the direction
  // still reflects: no refracted one exists)
  const auto entering_ratio = [](const BranchCount& b) {
    return b.c.entering || b.reflectance >= 1.0 ? b.reflectance
                                                : fresnel_dielectric(b.c.cos_i, 1.0, b.c.ior);
  };
  const auto swapped = [](const BranchCount& b) { return 1.0 - b.reflectance; };
  if (branch_p_value(counts, right, true) < k_seed_alpha &&
      branch_p_value(counts, entering_ratio, true) > 1e-3)
    return table + '\n' +
           diagnosis(
               "leaving the glass your reflected fraction follows Fresnel with the indices of entering (from 1 "
               "into n): leaving, the light goes from glass into air, eta_i = n, eta_t = 1 (R differs most "
               "near the critical angle)");
  if (branch_p_value(counts, swapped) > 1e-3)
    return table + '\n' +
           diagnosis("your path reflects with probability 1 - R: reflection's probability is R");
  return table + '\n' +
         diagnosis(
             "the fraction of samples that reflect is not the Fresnel reflectance R (table above)");
}

/// One seed of the branch test: 0 at the first invalid sample (its diagnosis in `wrong`), else
/// the chi-square p-value of the reflected counts against R (on rejection, the table of
/// fractions and a diagnosis in `table`, if still empty).
template <class S>
double dielectric_branch_p_value(S& subject, std::uint64_t seed, std::string& wrong,
                                 std::string& table) {
  std::vector<BranchCount> counts;
  for (std::size_t i = 0; i < k_a6_dielectric_cases.size(); ++i) {
    const DielectricCase& c = k_a6_dielectric_cases[i];
    const std::vector<DielectricQuery> queries = a6_branch_queries(c, seed, i);
    const std::vector<DielectricAnswer> answers = subject.a6_dielectric(c.ior, queries);
    BranchCount b{c, expect_dielectric(c.ior, queries.front()).reflectance, 0};
    for (std::size_t k = 0; k < queries.size(); ++k) {
      bool reflected = false;
      const std::string problem = judge_dielectric_sample(c.ior, queries[k], answers[k], reflected);
      if (!problem.empty()) {
        if (wrong.empty()) wrong = problem;
        return 0.0;  // an invalid sample rejects outright
      }
      b.reflected += reflected;
    }
    counts.push_back(b);
  }
  const double p = branch_p_value(counts, [](const BranchCount& b) { return b.reflectance; });
  if (p < k_seed_alpha && table.empty()) table = diagnose_branch_counts(counts);
  return p;
}

/// a6.4: every sample valid (judge_dielectric_sample) and the reflected fractions following R,
/// at the grading seeds (majority of 2 rejections at k_seed_alpha).
template <class S>
TaskResult check_dielectric_branches(S&& subject) {
  std::string wrong, table;
  const SeedVerdict v = at_grading_seeds(
      [&](std::uint64_t seed) { return dielectric_branch_p_value(subject, seed, wrong, table); });
  std::string message =
      fmt::format("the reflected fraction against Fresnel's R at {} angles, {} samples each: {}",
                  k_a6_dielectric_cases.size(), k_a6_branch_samples, v.describe());
  if (!v.passed()) message += '\n' + (wrong.empty() ? table : wrong);
  return {v.passed(), message};
}

}  // namespace mcrt::testing::assignment
