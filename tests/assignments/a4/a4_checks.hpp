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
#include "assignments/a4/a4_pixel_expected.hpp"
#include "assignments/a4/a4_produce.hpp"
#include "assignments/error_map.hpp"
#include "assignments/grading.hpp"
#include "geometry/camera.hpp"
#include "integration/statistics.hpp"
#include "render/path_tracer.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"
#include "stats/chi_square.hpp"
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
    return diagnosis(
        "the per-bounce weight averages 2a instead of a and never varies: is the cosine missing?");
  if (near(mean, 2.0, 0.05))
    return diagnosis(
        "the per-bounce weight averages 2a instead of a: is your pdf off by a factor of 2 (1/(4 pi) vs 1/(2 pi))?");
  if (near(mean, 4.0 / 3.0, 0.04))
    return diagnosis(
        "the per-bounce weight averages 4a/3: are directions cosine-distributed but divided by the uniform pdf 1/(2 pi)?");
  if (near(mean, 0.5, 0.05))
    return diagnosis("the per-bounce weight averages a/2: is a factor 2 missing (2 pi vs pi)?");
  if (!near(mean, 1.0, 0.05))
    return diagnosis(
        fmt::format("the per-bounce weight averages {:.2f}a instead of a = f_r cos / p", mean));
  return "";
}

/// The furnace of check_path_furnace (a = 0.5, Le = 1, k = 3) at one seed: the mean of 20000
/// paths z-tested against (1 - a^(k+1)) / (1 - a) with the closed-form variance, and their
/// variance z-tested against it, Sidak-combined (their mean in `mean`).
template <class Furnace>
double path_furnace_p_value(Furnace&& furnace, std::uint64_t seed, double& mean) {
  constexpr double a = 0.5;
  constexpr int k = 3, n = 20000;
  const double expected = furnace_radiance(a, 1.0, k),
               variance = furnace_radiance_variance(a, 1.0, k);
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
  return {v.passed(), fmt::format("furnace a = 0.5, k = 3: mean {:.5f} (expected {:.5f}); {}\n{}",
                                  mean, expected, v.describe(), d)};
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
  const Stats reference =
      region_stats<size, region>(camera, reference_tracer, 1024, seed ^ 0x5eedULL);
  const Stats student = stats_by_region<size, region>(sky(k, spp, seed), spp);
  double p_min = 1.0;
  for (int r = 0; r < regions * regions; ++r) {
    const RunningStats &s = student[static_cast<std::size_t>(r)],
                       &t = reference[static_cast<std::size_t>(r)];
    const double se = std::sqrt(s.variance() / static_cast<double>(s.count()) +
                                t.variance() / static_cast<double>(t.count()));
    const double p = z_test_p_value(s.mean(), t.mean(), se);
    if (z != nullptr) z->push_back(region_z(s.mean(), t.mean(), se));
    if (!(p >= p_min)) {
      p_min = p;
      if (std::abs(s.mean() - t.mean()) / se > worst_z)
        worst_z = std::abs(s.mean() - t.mean()) / se, worst = r;
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
  static_cast<TaskResult&>(result) = {
      v.passed(),
      fmt::format(
          "sky scene 16 x 16, k = 4, regions of 4 x 4 pixels: {}{}", v.describe(),
          v.passed()
              ? ""
              : fmt::format(
                    "\nthe worst region (pixels {}, {}) is {:.1f} standard errors from the reference at one seed",
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
  return [radiance](int k, int spp, std::uint64_t seed) {
    return sky_values(radiance, 16, k, spp, seed);
  };
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
  return
      [&subject](int k, int spp, std::uint64_t seed) { return subject.path_sky(16, k, spp, seed); };
}

// a4.2, the pixel's estimate. The checks judge bulk answers: `exact(spp, seed)` (pixel_exact_values),
// `rays(x, y, spp, seed, stream)` (pixel_ray_directions) and `furnace(albedo, depth, size, spp,
// seed)` (pixel_furnace_values); from subject() or from a known-wrong estimate_pixel (pixel_of).

/// The expected estimate of pixel number i (pixel_stream order) of pixel_camera() at the exact
/// check's spp number spp_index, from the table of a4_pixel_expected.hpp.
inline PixelEstimate expected_pixel_estimate(std::size_t spp_index, std::size_t i) {
  const std::array<double, 4>& e = k_a4_pixel_expected[spp_index][i];
  return {Color(e[0], e[1], e[2]), e[3]};
}

/// Exact agreement: every pixel of pixel_camera() at spp = 2 and 16, mean and standard error
/// against the expected table (the instructor's estimate from the same u's). Tolerance 1e-9 relative: a different
/// order of summation or a one- or two-pass variance changes the last few bits (1e-14), a
/// missing factor changes the result by 30% or more (the smallest, sqrt(15/16) at spp = 16).
template <class Exact>
TaskResult check_pixel_exact(Exact&& exact) {
  constexpr double tolerance = 1e-9;
  const Camera camera = pixel_camera();
  std::string first_miss;
  double mean_ratio = 0.0, se_ratio = 0.0;  // the student's over the checker's, at spp = 16
  bool zero_spread = true, centre_means = true;
  for (std::size_t spp_index = 0; spp_index < k_a4_pixel_spp.size(); ++spp_index) {
    const int spp = k_a4_pixel_spp[spp_index];
    const std::vector<double> values = exact(spp, k_a4_pixel_seed);
    RunningStats means, errors;
    for (int y = 0; y < camera.height(); ++y)
      for (int x = 0; x < camera.width(); ++x) {
        const std::size_t pixel = static_cast<std::size_t>(pixel_stream(x, y, camera.width())),
                          i = 4 * pixel;
        const PixelEstimate want = expected_pixel_estimate(spp_index, pixel);
        const Color mean(values[i], values[i + 1], values[i + 2]);
        const double se = values[i + 3];
        const Color centre = direction_radiance(camera.generate_ray(x, y, Vec2(0.5)));
        zero_spread = zero_spread && se == 0.0;
        centre_means = centre_means && std::abs(average(mean) - average(centre)) <=
                                           tolerance * std::abs(average(centre));
        const bool ok = std::abs(se - want.standard_error) <= tolerance * want.standard_error &&
                        std::abs(mean.r - want.mean.r) <= tolerance * std::abs(want.mean.r) &&
                        std::abs(mean.g - want.mean.g) <= tolerance * std::abs(want.mean.g) &&
                        std::abs(mean.b - want.mean.b) <= tolerance * std::abs(want.mean.b);
        if (!ok && first_miss.empty())
          first_miss = fmt::format(
              "pixel ({}, {}) at spp = {}: mean ({:.6g}, {:.6g}, {:.6g}), standard error {:.6g}; "
              "expected ({:.6g}, {:.6g}, {:.6g}), {:.6g}",
              x, y, spp, mean.r, mean.g, mean.b, se, want.mean.r, want.mean.g, want.mean.b,
              want.standard_error);
        means.add(average(mean) / average(want.mean));
        errors.add(se / want.standard_error);
      }
    mean_ratio = means.mean();
    se_ratio = errors.mean();
  }
  if (first_miss.empty())
    return {true, "every pixel's mean and standard error match the checker's, spp = 2 and 16"};
  std::string d;
  if (zero_spread && centre_means)
    d = diagnosis(
        "every pixel's mean is the radiance at its centre and the standard error is 0: is u always (0.5, 0.5) (no jitter)?");
  else if (near(mean_ratio, 16.0, 1e-6))
    d = diagnosis(
        "your mean is spp times the expected one: do you return the sum of the samples instead of their mean?");
  else if (near(mean_ratio, 1.0, 1e-6) && near(se_ratio, 4.0, 1e-6))
    d = diagnosis(
        "your standard error is sqrt(spp) times too large: is it sigma = sqrt(s^2), without the 1/spp of Var[mean] = sigma^2/spp?");
  else if (near(mean_ratio, 1.0, 1e-6) && near(se_ratio, std::sqrt(15.0 / 16.0), 1e-6))
    d = diagnosis(
        "your standard error is sqrt((spp - 1)/spp) times the expected one: do you divide the squared deviations by spp instead of spp - 1 (the biased variance)?");
  else if (near(mean_ratio, 1.0, 1e-6))
    d = diagnosis(fmt::format(
        "your means match but your standard errors are {:.3f} times the expected sqrt(s^2 / spp), s^2 of the channel mean average(L)",
        se_ratio));
  else
    d = diagnosis(
        "your means differ from the mean of the samples: take u = rng.uniform2() for each sample, in order, then trace camera.generate_ray(x, y, u)");
  return {false, fmt::format("the first pixel that differs: {}\n{}", first_miss, d)};
}

/// Where a ray of pixel_camera() crosses the image plane, in pixels (generate_ray inverted:
/// the screen's right and up axes are orthogonal to the view direction and to each other).
inline Vec2 image_position(const Camera& camera, const Vec3& direction) {
  const Camera::Frame f = camera.frame();
  const Vec3 d = direction / glm::dot(direction, f.forward);  // on the screen at unit distance
  const double a = glm::dot(d, f.right) / glm::dot(f.right, f.right);
  const double b = glm::dot(d, f.up) / glm::dot(f.up, f.up);
  return {(a + 0.5) * camera.width(), (0.5 - b) * camera.height()};
}

/// The jitter's chi-square at one seed: 10240 rays of pixel (5, 2), where they cross the pixel
/// in 16 x 16 equal cells, against 40 a cell (a ray outside the pixel fails at once).
/// `centred` says whether every ray went through the pixel's centre.
template <class Rays>
double jitter_p_value(Rays&& rays, std::uint64_t seed, bool& centred) {
  constexpr int x = 5, y = 2, cells = 16,
                n = cells * cells * 40;  // 40 a cell: Cochran's 5 with room
  const Camera camera = pixel_camera();
  std::vector<CellCount> counts(static_cast<std::size_t>(cells * cells));
  for (int c = 0; c < cells * cells; ++c)
    counts[static_cast<std::size_t>(c)] = {c % cells, c / cells, 0.0, n / double(cells * cells)};
  std::uint64_t outside = 0;
  centred = true;
  const std::vector<Vec3> directions = rays(x, y, n, seed, 7);
  for (const Vec3& d : directions) {
    const Vec2 p = image_position(camera, d) - Vec2(x, y);
    // 1e-9 pixels: generate_ray's round-off is 1e-15, a sample this close to the centre by chance 1e-18.
    centred = centred && std::abs(p.x - 0.5) < 1e-9 && std::abs(p.y - 0.5) < 1e-9;
    if (!(p.x >= -1e-9 && p.x <= 1.0 + 1e-9 && p.y >= -1e-9 && p.y <= 1.0 + 1e-9)) {
      ++outside;
      continue;
    }
    const int i = std::clamp(static_cast<int>(p.x * cells), 0, cells - 1),
              j = std::clamp(static_cast<int>(p.y * cells), 0, cells - 1);
    counts[static_cast<std::size_t>(j * cells + i)].observed += 1.0;
  }
  if (directions.size() != static_cast<std::size_t>(n)) return 0.0;
  return chi_square_test(counts, outside).p_value;
}

/// The jitter covers the pixel uniformly: jitter_p_value at the three grading seeds.
template <class Rays>
TaskResult check_pixel_jitter(Rays&& rays) {
  bool centred = false;
  const SeedVerdict v =
      at_grading_seeds([&](std::uint64_t seed) { return jitter_p_value(rays, seed, centred); });
  std::string d;
  if (!v.passed())
    d = centred
            ? diagnosis(
                  "every ray goes through the pixel's centre: is u always (0.5, 0.5) (no jitter)?")
            : diagnosis(
                  "the rays do not cover the pixel uniformly: u must be uniform in [0,1)^2, a new rng.uniform2() for each sample");
  return {v.passed(), fmt::format("pixel (5, 2), 10240 rays in 16 x 16 cells of the pixel: {}\n{}",
                                  v.describe(), d)};
}

/// The calibrated standard error at one seed: a 32 x 32 furnace render (a = 0.5, k = 3, 512
/// paths a pixel, furnace_path_law), the 1024 pixels' z = (mean - truth) / se, their variance z-tested
/// (variance_z_test_p_value, with the z's own kurtosis) against (spp - 1)/(spp - 3), Student's
/// t variance: the se is itself estimated, so Var[z] is 1 only as spp grows. Measured on the
/// furnace's skewed paths: 1.0036 at 512 (1.021 at 128, where the test rejected 3 in 1000
/// correct runs at 5e-4: hence 512). `z_variance` gets the z's variance.
template <class Furnace>
double calibration_p_value(Furnace&& furnace, std::uint64_t seed, double& z_variance) {
  constexpr double a = 0.5;
  constexpr int k = 3, size = 32, spp = 512;
  const double truth = furnace_radiance(a, 1.0, k);
  const std::vector<double> values = furnace(a, k, size, spp, seed);
  std::vector<double> z;
  for (std::size_t i = 0; i + 1 < values.size(); i += 2)
    z.push_back((values[i] - truth) / values[i + 1]);
  RunningStats s;
  for (double v : z) s.add(v);
  z_variance = s.variance();
  if (z.size() != static_cast<std::size_t>(size * size)) return 0.0;
  return variance_z_test_p_value(z, (spp - 1.0) / (spp - 3.0));
}

/// Calibration: calibration_p_value at the three grading seeds.
template <class Furnace>
TaskResult check_pixel_calibration(Furnace&& furnace) {
  double z_variance = 0.0;
  const SeedVerdict v = at_grading_seeds(
      [&](std::uint64_t seed) { return calibration_p_value(furnace, seed, z_variance); });
  std::string d;
  if (!v.passed()) {
    constexpr double spp = 512.0;
    if (near(z_variance, 1.0 / spp, 0.3))
      d = diagnosis(
          "the z-scores vary spp times too little: is your standard error sigma instead of sigma / sqrt(spp)?");
    else if (z_variance > 100.0)
      d = diagnosis(
          "the z-scores are far from 0: is your mean the furnace's mean (the mean of the samples, not their sum)?");
    else
      d = diagnosis(fmt::format(
          "the z-scores (mean - truth) / se have variance {:.3f}, not 1: your standard error is off by about a factor {:.2f}",
          z_variance, std::sqrt(z_variance)));
  }
  return {
      v.passed(),
      fmt::format(
          "furnace a = 0.5, k = 3, 32 x 32 pixels of 512 paths: variance of the z-scores {:.3f} at the last seed; {}\n{}",
          z_variance, v.describe(), d)};
}

/// a4.2's producers for an estimate_pixel run in this process (a known-wrong one).
template <class Estimate>
auto pixel_exact_of(Estimate estimate) {
  return
      [estimate](int spp, std::uint64_t seed) { return pixel_exact_values(estimate, spp, seed); };
}
template <class Estimate>
auto pixel_rays_of(Estimate estimate) {
  return [estimate](int x, int y, int spp, std::uint64_t seed, std::uint64_t stream) {
    return pixel_ray_directions(estimate, x, y, spp, seed, stream);
  };
}
template <class Estimate>
auto pixel_furnace_of(Estimate estimate) {
  return [estimate](double albedo, int depth, int size, int spp, std::uint64_t seed) {
    return pixel_furnace_values(estimate, albedo, depth, size, spp, seed);
  };
}

/// The same producers from a Subject.
template <class S>
auto pixel_exact_of_subject(S& subject) {
  return [&subject](int spp, std::uint64_t seed) { return subject.pixel_exact(spp, seed); };
}
template <class S>
auto pixel_rays_of_subject(S& subject) {
  return [&subject](int x, int y, int spp, std::uint64_t seed, std::uint64_t stream) {
    return subject.pixel_rays(x, y, spp, seed, stream);
  };
}
template <class S>
auto pixel_furnace_of_subject(S& subject) {
  return [&subject](double albedo, int depth, int size, int spp, std::uint64_t seed) {
    return subject.pixel_furnace(albedo, depth, size, spp, seed);
  };
}

}  // namespace mcrt::testing::assignment
