#pragma once
// The grading procedures of assignment a5 (variance reduction). They judge the bulk answers
// of `p`, a Subject or an A5Producer (a5_produce.hpp): furnace paths (a5_paths), Cornell box
// samples (a5_regions), wall samples (a5_wall) of the estimator an A5Estimator names:
//   a5.1 estimate_path_radiance_roulette(scene, ray, roulette, rng, count)
//   a5.2 estimate_importance_path_radiance(scene, ray, max_depth, pdf, rng, count)
//   a5.3 estimate_nee_radiance(scene, ray, path_end, rng, count)
// The furnace (albedo a, Le = 1 everywhere) has closed forms for all three; NEE is also
// compared, region by region, with a4's path tracer on a small Cornell box.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "assignments/a4/a4_checks.hpp"
#include "assignments/a5/a5_produce.hpp"
#include "assignments/grading.hpp"
#include "geometry/camera.hpp"
#include "integration/statistics.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/next_event_estimation.hpp"
#include "render/path_tracer.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "sampling/cosine_power.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

/// Whether a furnace path's value (a = albedo, Le = 1, depth k) is exact: Le (1 + a + ... + a^k),
/// or that of a path ended early at a direction of density 0 (u on the edge of [0,1)^2, 2^-32
/// per bounce): Le (1 + ... + a^j), j < k, allowed at most `early` times in all.
inline bool exact_furnace_path(double value, double a, int k, double tolerance, int& early) {
  if (std::abs(value - furnace_radiance(a, 1.0, k)) <= tolerance * value) return true;
  for (int j = 0; j < k; ++j)
    if (std::abs(value - furnace_radiance(a, 1.0, j)) <= tolerance * value) return ++early <= 2;
  return false;
}

// ---------------------------------------------------------------------------------------------
// a5.1 Russian roulette

/// E[L] in the furnace of fixed-q roulette whose survivors are NOT divided by q: vertex j > d
/// is reached with probability q^(j-d) and keeps the weight a^j, so
///   Le ((1 - a^(d+1)) / (1 - a) + a^d a q / (1 - a q)).
inline double furnace_roulette_mean_without_division(double a, int d, double q) {
  return furnace_radiance(a, 1.0, d) + std::pow(a, d) * a * q / (1.0 - a * q);
}

/// E[L] when roulette runs before Le(x_j) is added: a path stopped at x_j (j >= d) loses it, so
/// term j keeps a^j q: Le ((1 - a^d) / (1 - a) + q a^d / (1 - a)).
inline double furnace_roulette_mean_before_emission(double a, int d, double q) {
  return (d > 0 ? furnace_radiance(a, 1.0, d - 1) : 0.0) + q * std::pow(a, d) / (1.0 - a);
}

/// The roulette furnace of check_roulette_furnace at one seed: its p-value (adding the mean
/// radiance and mean rays to the sums given).
template <class P>
double roulette_furnace_p_value(P&& producer, std::uint64_t seed, double& mean_sum,
                                double& rays_sum) {
  constexpr double a = 0.5, q = 0.7;
  constexpr int d = 2, n = 20000;
  const Roulette roulette{d, RoulettePolicy::fixed, q, 0.05};
  const double expected = furnace_radiance_untruncated(a, 1.0);
  const double variance = furnace_roulette_variance(a, 1.0, d, q);
  const double rays = furnace_roulette_mean_rays(d, q), rays_variance = q / ((1.0 - q) * (1.0 - q));
  const auto paths = producer.a5_paths(roulette_estimator(roulette), a, n, seed, 61);
  std::vector<double> values;
  RunningStats L, R;
  for (const FurnacePath& p : paths) {
    values.push_back(p.radiance);
    L.add(p.radiance);
    R.add(static_cast<double>(p.rays));
  }
  mean_sum += L.mean();
  rays_sum += R.mean();
  const double p_mean = z_test_p_value(L.mean(), expected, std::sqrt(variance / n));
  const double p_rays = z_test_p_value(R.mean(), rays, std::sqrt(rays_variance / n));
  return sidak_p_value(std::min({p_mean, p_rays, variance_z_test_p_value(values, variance)}), 3);
}

/// The furnace (a = 0.5, Le = 1), fixed q = 0.7 after d = 2: 20000 paths' mean z-tested
/// against Le / (1 - a) = 2 (no depth cut, no bias), their variance against the closed form
/// (finite: q > 4 a^2 / 3), and their mean ray count against d + 1/(1 - q) (a geometric
/// length, variance q / (1 - q)^2); Sidak-combined, at the three grading seeds.
template <class P>
TaskResult check_roulette_furnace(P&& producer) {
  constexpr double a = 0.5, q = 0.7;
  constexpr int d = 2;
  const double expected = furnace_radiance_untruncated(a, 1.0),
               rays = furnace_roulette_mean_rays(d, q);
  double mean_sum = 0.0, rays_sum = 0.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    return roulette_furnace_p_value(producer, seed, mean_sum, rays_sum);
  });
  const double mean = mean_sum / k_seeds, mean_rays = rays_sum / k_seeds;
  std::string d_text;
  if (!v.passed()) {
    const double r = mean / expected;
    if (near(mean, furnace_roulette_mean_without_division(a, d, q), 0.01))
      d_text = diagnosis(fmt::format(
          "your mean is {:.3f}x the expected value, that of roulette whose survivors keep "
          "their weight: is the survivor's weight divided by q?",
          r));
    else if (near(mean, furnace_roulette_mean_before_emission(a, d, q), 0.01))
      d_text = diagnosis(fmt::format(
          "your mean is {:.3f}x the expected value: a path stopped at x_j loses Le(x_j): "
          "add the emission before the roulette",
          r));
    else if (near(mean, expected, 0.01) && near(mean_rays, 1.0 / (1.0 - q), 0.02))
      d_text = diagnosis(
          fmt::format("paths trace {:.2f} rays on average instead of d + 1/(1 - q) = {:.2f}: "
                      "does the roulette start at vertex min_depth, not at 0?",
                      mean_rays, rays));
    else if (near(mean, expected, 0.01) && !near(mean_rays, rays, 0.02))
      d_text = diagnosis(
          fmt::format("paths trace {:.2f} rays on average instead of d + 1/(1 - q) = {:.2f}: does "
                      "a path go on with probability q (u < q), from vertex min_depth on?",
                      mean_rays, rays));
    else
      d_text = diagnose_mean_ratio(mean, expected);
  }
  return {v.passed(),
          fmt::format("furnace a = 0.5, fixed q = 0.7 after d = 2: mean {:.5f} (expected {:.5f}), "
                      "rays {:.3f} (expected {:.3f}); {}\n{}",
                      mean, expected, mean_rays, rays, v.describe(), d_text)};
}

// ---------------------------------------------------------------------------------------------
// a5.2 importance sampling

/// The furnace's per-bounce weight w = f_r cos / p at depth 1 (L = 1 + w): its mean and
/// spread over 4000 paths, in units of a, with the pdf `pdf`.
template <class P>
RunningStats furnace_bounce_weights(P&& producer, const HemispherePdf& pdf, double a) {
  RunningStats w;
  for (const FurnacePath& p : producer.a5_paths(importance_estimator(1, pdf), a, 4000, 99, 78))
    w.add((p.radiance - 1.0) / a);
  return w;
}

/// With the cosine pdf the weight is f_r cos / p = (a / pi) cos / (cos / pi) = a exactly, so
/// in the furnace (a = 0.5, k = 3) every one of 2000 paths returns Le (1 + a + a^2 + a^3):
/// checked path by path (to 1e-9), no statistics (exact_furnace_path: but for at most two
/// paths ended early at a direction of density 0).
template <class P>
TaskResult check_cosine_furnace_is_exact(P&& producer) {
  constexpr double a = 0.5;
  constexpr int k = 3;
  const HemispherePdf cosine = cosine_power_pdf(1);
  const double expected = furnace_radiance(a, 1.0, k);
  int wrong = 0, early = 0;
  double first_wrong = 0.0;
  for (const FurnacePath& p : producer.a5_paths(importance_estimator(k, cosine), a, 2000, 7, 79))
    if (!exact_furnace_path(p.radiance, a, k, 1e-9, early) && wrong++ == 0)
      first_wrong = p.radiance;
  if (wrong == 0)
    return {true, fmt::format("furnace a = 0.5, k = 3, cosine pdf: all 2000 paths return {:.6f}",
                              expected)};
  const RunningStats w = furnace_bounce_weights(producer, cosine, a);
  std::string d;
  const double spread = std::sqrt(w.variance());
  if (!std::isfinite(w.mean()))
    d = diagnosis("the weight is not finite (NaN or inf): a division by a pdf of 0?");
  else if (spread < 1e-9 && near(w.mean(), k_inv_pi, 0.01))
    d = diagnosis(
        "the per-bounce weight is a/pi instead of a, at every bounce: is the cosine pdf missing its 1/pi (p = cos(theta)/pi)?");
  else if (spread < 1e-9 && near(w.mean(), k_pi, 0.01))
    d = diagnosis(
        "the per-bounce weight is pi a instead of a: is the cosine pdf cos(theta) pi instead of cos(theta)/pi?");
  else if (spread < 1e-9)
    d = diagnosis(
        fmt::format("the per-bounce weight is {:.3f}a at every bounce instead of a = f_r cos / p",
                    w.mean()));
  else if (near(w.mean(), 4.0 / 3.0, 0.05))
    d = diagnosis(
        "the per-bounce weight averages 4a/3 and varies: cosine directions divided by the uniform pdf 1/(2 pi)?");
  else
    d = diagnosis(fmt::format(
        "the per-bounce weight averages {:.3f}a with spread {:.3f}a; with the cosine pdf it is a, "
        "always: are the direction drawn and the pdf divided by the same (sample_hemisphere, "
        "hemisphere_pdf of the same pdf)?",
        w.mean(), spread));
  return {
      false,
      fmt::format(
          "furnace a = 0.5, k = 3, cosine pdf: {} of 2000 paths differ from Le (1 + a + a^2 + a^3) = "
          "{:.6f} (the first: {:.6f})\n{}",
          wrong, expected, first_wrong, d)};
}

/// Any pdf gives the same mean; the variance is the pdf's (importance_path_tracer.hpp). The
/// furnace (a = 0.5, k = 3) with `pdf`: 20000 paths' mean z-tested against the closed form,
/// and for the uniform pdf their variance too (Sidak-combined), at the three grading seeds.
/// Only the mean for cos^m, m >= 2: its weight w ~ 1/cos^(m-1) has an infinite fourth moment,
/// so the sample variance has no standard error to test it with.
template <class P>
double importance_furnace_p_value(P&& producer, const HemispherePdf& pdf, std::uint64_t seed,
                                  double& mean_sum) {
  constexpr double a = 0.5;
  constexpr int k = 3, n = 20000;
  const double expected = furnace_radiance(a, 1.0, k),
               variance = furnace_radiance_variance(pdf, a, 1.0, k);
  std::vector<double> values;
  RunningStats s;
  for (const FurnacePath& p : producer.a5_paths(importance_estimator(k, pdf), a, n, seed, 62)) {
    values.push_back(p.radiance);
    s.add(p.radiance);
  }
  mean_sum += s.mean();
  const double p_mean = z_test_p_value(s.mean(), expected, std::sqrt(variance / n));
  if (pdf.kind != HemispherePdf::uniform) return p_mean;
  return sidak_p_value(std::min(p_mean, variance_z_test_p_value(values, variance)), 2);
}

template <class P>
TaskResult check_importance_furnace(P&& producer, const HemispherePdf& pdf) {
  const double expected = furnace_radiance(0.5, 1.0, 3);
  double mean_sum = 0.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    return importance_furnace_p_value(producer, pdf, seed, mean_sum);
  });
  const double mean = mean_sum / k_seeds;
  std::string d;
  if (!v.passed()) {
    const RunningStats w = furnace_bounce_weights(producer, pdf, 0.5);
    if (!near(w.mean(), 1.0, 0.05))
      d = diagnosis(fmt::format(
          "with the {} pdf the per-bounce weight averages {:.3f}a instead of a: is f_r cos / p "
          "divided by the pdf of the direction drawn (hemisphere_pdf(pdf, cos theta))?",
          pdf_name(pdf), w.mean()));
    else
      d = diagnosis(fmt::format(
          "the mean is right but not the variance with the {} pdf: are the directions drawn "
          "from that pdf (sample_hemisphere(pdf, u))?",
          pdf_name(pdf)));
  }
  return {v.passed(),
          fmt::format("furnace a = 0.5, k = 3, {} pdf: mean {:.5f} (expected {:.5f}); {}\n{}",
                      pdf_name(pdf), mean, expected, v.describe(), d)};
}

// ---------------------------------------------------------------------------------------------
// a5.3 next-event estimation

/// In the furnace (unit sphere, the whole sphere the light) every light sample gives exactly
/// f_r Le cos_x cos_y / (r^2 p_A) = a Le, and the cosine bounce weighs a: each of 2000 paths at
/// k = 3 returns Le (1 + a + a^2 + a^3), checked path by path (to 1e-6; exact_furnace_path).
template <class P>
TaskResult check_nee_furnace_is_exact(P&& producer) {
  constexpr double a = 0.5;
  constexpr int k = 3;
  const double expected = furnace_radiance(a, 1.0, k);
  RunningStats all;
  int wrong = 0, early = 0;
  for (const FurnacePath& p : producer.a5_paths(nee_estimator(nee_depth_cut(k)), a, 2000, 11, 80)) {
    all.add(p.radiance);
    wrong += !exact_furnace_path(p.radiance, a, k, 1e-6, early);
  }
  if (wrong == 0)
    return {true, fmt::format("furnace a = 0.5, k = 3: all 2000 paths return {:.6f}", expected)};
  // The direct light's share: L - Le over (1 + a + a^2 + a^3) - 1, the sum of the direct terms.
  const double direct = (all.mean() - 1.0) / (expected - 1.0), spread = std::sqrt(all.variance());
  std::string d;
  if (!std::isfinite(all.mean()))
    d = diagnosis("your result is not finite (NaN or inf): a division by a pdf of 0?");
  else if (std::abs(all.mean() - furnace_radiance(a, 1.0, k + 1)) < 1e-6 && spread < 1e-6)
    d = diagnosis(fmt::format(
        "every path returns Le (1 + a + ... + a^(k+1)) = {:.6f}, one light sample too many: is the "
        "path cut at depth k only after the light sample of its last vertex? That sample's light "
        "travels k + 1 segments: check the depth before sampling the light",
        furnace_radiance(a, 1.0, k + 1)));
  else if (direct > 1.6 && direct < 2.4 && spread > 1e-3)
    // p_w = p_A r^2 for p_A r^2 / cos(theta_y): each sample 1 / cos(theta_y) too large, and
    // cos(theta_y) is cosine-distributed here, so the direct light averages E[1/cos] = 2 with
    // an infinite variance (emission counted twice gives exactly 2x, no spread)
    d = diagnosis(fmt::format(
        "direct light is {:.2f}x and varies wildly from path to path, as 1 / cos(theta_y) does "
        "(its mean here is 2); every light sample here should give exactly a Le: is cos(theta_y), "
        "the cosine at the light, left out of p_w = p_A r^2 / cos(theta_y)?",
        direct));
  else if (near(direct, 2.0, 0.01) && spread < 1e-6)
    d = diagnosis(
        "direct light is 2x: is emission counted by both the light sample and the BSDF ray? (after the camera "
        "ray, only the shadow ray adds Le)");
  else if (near(direct, 0.0, 1e-3) || direct < 0.1)
    d = diagnosis(fmt::format(
        "direct light is {:.2f}x: almost no shadow ray reaches the light: does it stop short of the "
        "light point (the light itself must not block it)?",
        direct));
  else if (spread > 1e-3 && !near(direct, 1.0, 0.05))
    d = diagnosis(fmt::format(
        "direct light is {:.2f}x and varies from path to path; every light sample here should give "
        "exactly a Le: is p_A converted to solid angle, p_w = p_A r^2 / cos(theta_y)?",
        direct));
  else
    d = diagnose_mean_ratio(all.mean(), expected);
  return {
      false,
      fmt::format(
          "furnace a = 0.5, k = 3: {} of 2000 paths differ from Le (1 + a + a^2 + a^3) = {:.6f} "
          "(mean {:.6f}, spread {:.3g})\n{}",
          wrong, expected, all.mean(), spread, d)};
}

/// Region by region against a4's path tracer: the Cornell box (its lamp at 3x its area, same
/// power) at 16 x 16 pixels, k = 3, cut into 4 x 4 regions of 4 x 4 pixels. Each region's NEE
/// mean over 1024 paths (64 per pixel) is z-tested against the path tracer's (uniform
/// directions, 1024 per pixel, at another seed: the same expectation, independent), the
/// standard error from both sample variances; the 16 p-values Sidak-combined, at the three
/// grading seeds.
/// One seed of check_nee_regions: the Sidak-combined p-value of the 16 regions (and the worst
/// region: its index, z and ratio of means, when it is worse than `worst_z`).
template <class P>
double nee_regions_p_value(P&& producer, std::uint64_t seed, int& worst, double& worst_z,
                           double& worst_ratio, int lamp_parts = 1) {
  constexpr int size = 16, region = 4, regions = size / region, k = 3;
  const Scene scene = make_cornell_box(3.0, lamp_parts);
  const Camera camera(scene.camera, size, size);
  using Stats = std::array<RunningStats, regions * regions>;
  const auto collect = [&](auto&& estimate, int spp, std::uint64_t at_seed) {
    return region_stats<size, region>(camera, estimate, spp, at_seed);
  };
  const Stats reference =
      collect([&](const Ray& ray, Rng& rng,
                  RayCount& count) { return estimate_path_radiance(scene, ray, k, rng, count); },
              1024, seed ^ 0xa5a5ULL);
  const Stats student = stats_by_region<size, region>(
      producer.a5_regions(nee_estimator(nee_depth_cut(k)), lamp_parts, size, 64, seed), 64);
  double p_min = 1.0;
  for (int r = 0; r < regions * regions; ++r) {
    const RunningStats &s = student[static_cast<std::size_t>(r)],
                       &t = reference[static_cast<std::size_t>(r)];
    const double se = std::sqrt(s.variance() / static_cast<double>(s.count()) +
                                t.variance() / static_cast<double>(t.count()));
    const double p = z_test_p_value(s.mean(), t.mean(), se);
    if (!(p >= p_min)) {
      p_min = p;
      const double z = std::abs(s.mean() - t.mean()) / se;
      if (!(z <= worst_z)) worst_z = z, worst = r, worst_ratio = s.mean() / t.mean();
    }
  }
  return sidak_p_value(p_min, regions * regions);
}

/// check_nee_regions on the box whose lamp is in `lamp_parts` strips: the verdict, and the
/// worst region's distance when it fails (a diagnosis of the 1/N_lights when it is off by a
/// factor and there are several lights).
template <class P>
TaskResult nee_regions_verdict(P&& producer, int lamp_parts, const std::string& scene) {
  constexpr int regions = 4;
  int worst = 0;
  double worst_z = 0.0, worst_ratio = 1.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    return nee_regions_p_value(producer, seed, worst, worst_z, worst_ratio, lamp_parts);
  });
  std::string message =
      fmt::format("{} 16 x 16, k = 3, regions of 4 x 4 pixels: {}", scene, v.describe());
  if (v.passed()) return {true, message};
  const int column = worst % regions, row = worst / regions;
  // A wrong 1/N_lights is invisible with one light: if the one-light box fails too, the bug is
  // another (emission at every vertex, a missing cos(theta_y), ...), which its tests name.
  const auto one_light_fails = [&] {
    int w = 0;
    double z = 0.0, ratio = 1.0;
    return !at_grading_seeds([&](std::uint64_t seed) {
              return nee_regions_p_value(producer, seed, w, z, ratio, 1);
            }).passed();
  };
  if (lamp_parts > 1 && one_light_fails()) {
    message += fmt::format("\nregion (column {}, row {}) is {:.2f}x the path tracer\n", column, row,
                           worst_ratio);
    message += diagnosis(
        "the box with one light fails too, so the light pick's 1/N_lights is not what is wrong here: "
        "fix what the NEE furnace and the one-light region test say first");
  } else if (lamp_parts > 1 && (worst_ratio < 0.75 || worst_ratio > 1.3)) {
    message += '\n';  // apart: "\n" + a temporary trips a false -Wrestrict in g++ 12
    message += diagnosis(
        fmt::format("region (column {}, row {}) is {:.2f}x the path tracer: with {} lights, does "
                    "the light sample's pdf include the 1/N_lights of picking one, once "
                    "(p_w = (p_A / N) r^2 / cos(theta_y))?",
                    column, row, worst_ratio, lamp_parts));
  } else {
    message += fmt::format(
        "\nregion (column {}, row {}) is {:.1f} standard errors from the path tracer ({:.2f}x its mean)",
        column, row, worst_z, worst_ratio);
  }
  return {false, message};
}

template <class P>
TaskResult check_nee_regions(P&& producer) {
  return nee_regions_verdict(producer, 1, "Cornell box");
}

/// The same with the lamp cut into two strips side by side (make_cornell_box's lamp_parts): the
/// same light and image, but the light sampler picks one of two emitters, so its pdf carries
/// the 1/2 of that pick. Forgetting it (p_A for p_A / 2) halves the direct light: every region
/// is darker than the path tracer's (and brighter if the 1/N is applied twice over).
template <class P>
TaskResult check_nee_two_lights(P&& producer) {
  return nee_regions_verdict(producer, 2, "Cornell box with its lamp in two parts,");
}

/// a5.3 where a sphere light shows more than its cap: cornell-spheres' light is a ball sunk
/// into the ceiling, and only its cap shows in the room; but the top rows' camera rays start
/// above the ceiling (140 units in front of the eye) and meet the left wall between the ceiling
/// and the light, where the light is seen beyond its cap. 4000 rays onto that strip of wall at
/// depth 1 (the wall's direct light): NEE's mean against a4's path tracer's (4000 paths at
/// another seed), a z-test from both sample variances, at the three grading seeds.
template <class P>
double nee_beyond_cap_p_value(P&& producer, std::uint64_t seed, double& ratio) {
  const Scene scene = make_cornell_spheres();
  constexpr int n = 4000;
  const auto collect = [&](auto&& estimate, std::uint64_t at_seed) {
    RunningStats stats;
    for (int i = 0; i < n; ++i) {
      Rng rng(at_seed, stream_index(70, static_cast<std::uint64_t>(i)));
      // y in [82, 84], z in [130, 160]: under the light (above y = 85.2 at z = 130 a point is
      // inside the light sphere, which no camera ray reaches)
      const Vec2 u = rng.uniform2();
      const Ray ray{{1.5, 82.0 + 2.0 * u.x, 130.0 + 30.0 * u.y}, {-1.0, 0.0, 0.0}};
      RayCount count;
      stats.add(average(estimate(ray, rng, count)));
    }
    return stats;
  };
  const RunningStats reference =
      collect([&](const Ray& ray, Rng& rng,
                  RayCount& count) { return estimate_path_radiance(scene, ray, 1, rng, count); },
              seed ^ 0x5a5aULL);
  RunningStats student;
  for (double x : producer.a5_wall(nee_estimator(nee_depth_cut(1)), n, seed)) student.add(x);
  ratio = student.mean() / reference.mean();
  return z_test_p_value(student.mean(), reference.mean(),
                        std::sqrt(student.variance() / n + reference.variance() / n));
}

template <class P>
TaskResult check_nee_light_beyond_cap(P&& producer) {
  double ratio = 1.0;
  const SeedVerdict v = at_grading_seeds(
      [&](std::uint64_t seed) { return nee_beyond_cap_p_value(producer, seed, ratio); });
  std::string d;
  // The furnace's paths are exact: if they are wrong, the bug is there to see in every scene
  // (emission at every vertex, a missing cos(theta_y)), not in how the cap is sampled.
  const bool furnace_wrong = !v.passed() && !check_nee_furnace_is_exact(producer).passed;
  if (furnace_wrong)
    d = diagnosis(
        "the NEE furnace's exact paths are wrong too, so the cap of the sphere light is not what is wrong "
        "here: fix what the furnace test says first");
  else if (!v.passed() && ratio < 0.1)
    d = diagnosis(
        "almost no light reaches this wall through your shadow rays, though the light is in plain view: "
        "do you sample only the cap of the sphere light? That cap is all of it the room can see, not all "
        "a point above the ceiling can see: sample_emitter(scene, e, x, u) aims at the part x can see "
        "(give it the point the shadow ray starts from)");
  else if (!v.passed())
    d = diagnose_mean_ratio(ratio, 1.0);
  return {v.passed(),
          fmt::format("cornell-spheres, the left wall above the ceiling, depth 1, your NEE against "
                      "a4's path tracer ({:.2f}x its mean): {}\n{}",
                      ratio, v.describe(), d)};
}

}  // namespace mcrt::testing::assignment
