#pragma once
// The grading procedures of assignment a4 (the path tracer). They judge bulk answers:
// `furnace(albedo, depth, n, seed, block)` the values of n furnace paths (furnace_values) and
// `sky(k, spp, seed)` every sample of the 16 x 16 sky render (sky_values); the tests take them
// from subject(), diagnosis_test.cpp from known-wrong tracers (furnace_of, sky_of).

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/a4/a4_produce.hpp"
#include "assignments/error_map.hpp"
#include "assignments/grading.hpp"
#include "geometry/camera.hpp"
#include "integration/statistics.hpp"
#include "render/path_tracer.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"
#include "stats/hypothesis.hpp"

namespace mcrt::testing::assignment {

/// What one bounce's weight w = f_r cos / p looks like: at depth 1 in the furnace (Le = 1),
/// L = 1 + w. A correct tracer has E[w] = a and Var[w] = a^2 / 3.
template <class Furnace>
std::string diagnose_bounce_weight(Furnace&& furnace, double a) {
  RunningStats w;
  for (double L : furnace(a, 1, 4000, 99, 77)) w.add(L - 1.0);
  const double mean = w.mean() / a;  // in units of a
  if (near(mean, 2.0, 0.05) && w.variance() < 1e-12)
    return diagnosis("the per-bounce weight averages 2a instead of a and never varies: is the cosine missing?");
  if (near(mean, 2.0, 0.05))
    return diagnosis("the per-bounce weight averages 2a instead of a: is your pdf off by a factor of 2 (1/(4 pi) vs 1/(2 pi))?");
  if (near(mean, 4.0 / 3.0, 0.04))
    return diagnosis("the per-bounce weight averages 4a/3: are directions cosine-distributed but divided by the uniform pdf 1/(2 pi)?");
  if (near(mean, 0.5, 0.05))
    return diagnosis("the per-bounce weight averages a/2: is a factor 2 missing (2 pi vs pi)?");
  if (!near(mean, 1.0, 0.05))
    return diagnosis(fmt::format("the per-bounce weight averages {:.2f}a instead of a = f_r cos / p", mean));
  return "";
}

/// The furnace of check_path_furnace (a = 0.5, Le = 1, k = 3) at one seed: the mean of 20000
/// paths z-tested against (1 - a^(k+1)) / (1 - a) with the closed-form variance, and their
/// variance z-tested against it, Sidak-combined (their mean in `mean`).
template <class Furnace>
double path_furnace_p_value(Furnace&& furnace, std::uint64_t seed, double& mean) {
  constexpr double a = 0.5;
  constexpr int k = 3, n = 20000;
  const double expected = furnace_radiance(a, 1.0, k), variance = furnace_radiance_variance(a, 1.0, k);
  const std::vector<double> values = furnace(a, k, n, seed, 51);
  RunningStats s;
  for (double x : values) s.add(x);
  mean = s.mean();
  const double p_mean = z_test_p_value(s.mean(), expected, std::sqrt(variance / n));
  return sidak_p_value(std::min(p_mean, variance_z_test_p_value(values, variance)), 2);
}

/// The furnace: path_furnace_p_value at the three grading seeds. Also the depth off-by-one.
template <class Furnace>
TaskResult check_path_furnace(Furnace&& furnace) {
  constexpr double a = 0.5;
  constexpr int k = 3;
  const double expected = furnace_radiance(a, 1.0, k);
  double mean_sum = 0.0;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    double mean = 0.0;
    const double p = path_furnace_p_value(furnace, seed, mean);
    mean_sum += mean;
    return p;
  });
  const double mean = mean_sum / k_seeds;
  std::string d;
  if (!v.passed()) {
    d = diagnose_bounce_weight(furnace, a);
    if (d.empty() && near(mean, furnace_radiance(a, 1.0, k + 1), 0.005))
      d = diagnosis("your mean is that of k + 1 bounces: does your loop stop one bounce late?");
    if (d.empty() && near(mean, furnace_radiance(a, 1.0, k - 1), 0.005))
      d = diagnosis("your mean is that of k - 1 bounces: does your loop stop one bounce early?");
    if (d.empty()) d = diagnose_mean_ratio(mean, expected);
  }
  return {v.passed(), fmt::format("furnace a = 0.5, k = 3: mean {:.5f} (expected {:.5f}); {}\n{}", mean,
                                  expected, v.describe(), d)};
}

/// Region by region against a reference: the sky scene at 16 x 16 pixels, k = 4, cut into
/// 4 x 4 regions of 4 x 4 pixels. Each region's mean over 4096 paths (256 per pixel) is
/// z-tested against the reference's (a3's recursion with N = 1 branch, 1024 paths per pixel
/// at another seed, drawn anew at each grading seed: independent of the student's, and in
/// every kit of a4, where the tracers of chapters 06-08 are withheld), the standard error of
/// the difference taken from both sample variances; the 16 p-values are Sidak-combined, at the three seeds.
/// One seed of check_reference_regions: the Sidak-combined p-value of the 16 regions (and the
/// worst region: its index and z, when it is worse than `worst_z`; each region's signed z in
/// `z`, row by row, when given).
template <class Sky>
double reference_regions_p_value(Sky&& sky, std::uint64_t seed, int& worst, double& worst_z,
                                 std::vector<double>* z = nullptr) {
  constexpr int size = 16, region = 4, regions = size / region, k = 4, spp = 256;
  const Scene scene = make_sky_scene();
  const Camera camera(scene.camera, size, size);
  using Stats = std::array<RunningStats, regions * regions>;
  const auto reference_tracer = [&](const Ray& ray, Rng& rng, RayCount& count) {
    return incident_radiance(scene, ray, 0, RecursiveSettings{1, k}, rng, count);
  };
  // A reference of its own per seed: the three verdicts stay independent.
  const Stats reference = region_stats<size, region>(camera, reference_tracer, 1024, seed ^ 0x5eedULL);
  const Stats student = stats_by_region<size, region>(sky(k, spp, seed), spp);
  double p_min = 1.0;
  for (int r = 0; r < regions * regions; ++r) {
    const RunningStats &s = student[static_cast<std::size_t>(r)], &t = reference[static_cast<std::size_t>(r)];
    const double se = std::sqrt(s.variance() / static_cast<double>(s.count()) + t.variance() / static_cast<double>(t.count()));
    const double p = z_test_p_value(s.mean(), t.mean(), se);
    if (z != nullptr) z->push_back(region_z(s.mean(), t.mean(), se));
    if (!(p >= p_min)) {
      p_min = p;
      if (std::abs(s.mean() - t.mean()) / se > worst_z) worst_z = std::abs(s.mean() - t.mean()) / se, worst = r;
    }
  }
  return sidak_p_value(p_min, regions * regions);
}

/// The error map of the sky render: 4 x 4 regions, labelled by their pixels.
inline RegionErrorMap make_sky_error_map() {
  std::vector<std::string> columns, rows;
  for (int i = 0; i < 4; ++i) {
    columns.push_back(fmt::format("x {}-{}", 4 * i, 4 * i + 3));
    rows.push_back(fmt::format("y {}-{}", 4 * i, 4 * i + 3));
  }
  return make_error_map(4, 4, columns, rows);
}

template <class Sky>
RegionResult check_reference_regions(Sky&& sky) {
  constexpr int regions = 4;
  int worst = 0;
  double worst_z = 0.0;
  RegionErrorMap map = make_sky_error_map();
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    std::vector<double> z;
    const double p = reference_regions_p_value(sky, seed, worst, worst_z, &z);
    add_seed(map, z);
    return p;
  });
  RegionResult result;
  result.map = map;
  static_cast<TaskResult&>(result) = {v.passed(), fmt::format("sky scene 16 x 16, k = 4, regions of 4 x 4 pixels: {}{}", v.describe(),
                                  v.passed() ? "" : fmt::format("\nthe worst region (pixels {}, {}) is {:.1f} standard errors from the reference at one seed",
                                                                map.column_labels[static_cast<std::size_t>(worst % regions)],
                                                                map.row_labels[static_cast<std::size_t>(worst / regions)], worst_z))};
  return result;
}

/// The bulk producers of check_path_furnace and check_reference_regions for a tracer run in
/// this process (a known-wrong one, in diagnosis_test.cpp).
template <class Radiance>
auto furnace_of(Radiance radiance) {
  return [radiance](double albedo, int depth, int n, std::uint64_t seed, std::uint64_t block) {
    return furnace_values(radiance, albedo, depth, n, seed, block);
  };
}

template <class Radiance>
auto sky_of(Radiance radiance) {
  return [radiance](int k, int spp, std::uint64_t seed) { return sky_values(radiance, 16, k, spp, seed); };
}

/// The same producers from a Subject (its a4 requests).
template <class S>
auto furnace_of_subject(S& subject) {
  return [&subject](double albedo, int depth, int n, std::uint64_t seed, std::uint64_t block) {
    return subject.path_furnace(albedo, depth, n, seed, block);
  };
}

template <class S>
auto sky_of_subject(S& subject) {
  return [&subject](int k, int spp, std::uint64_t seed) { return subject.path_sky(16, k, spp, seed); };
}

}  // namespace mcrt::testing::assignment
