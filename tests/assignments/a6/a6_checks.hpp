#pragma once
// The grading procedures of assignment a6 (glossy surfaces and multiple importance sampling).
// Each judges what a producer returns (a Subject: the student's code in-process or in the
// subject program; diagnosis_test.cpp: known-wrong variants):
//   a6.1 the Phong lobe round +z: the chi-square test of tests/stats/ at m = 10 (three seeds,
//        majority of 2 rejections at 5e-4, grading.hpp), its pdf integrating to 1, the pdf
//        round a tilted mirror direction, and the sharp lobe's digits at m = 1e4;
//   a6.2 the balance and power heuristics against a table of exact values, and the weights of a
//        direction summing to 1;
//   a6.3 the MIS estimator of Veach's plates, per plate x light region, against a reference
//        rendered once by the instructor's solution, and its variance at equal rays against
//        the single strategies (light sampling alone, BSDF sampling alone).
// Measured by measure_assignment_fairness (docs/assignments/fairness.json; README "Fairness"):
// the single-seed p-values of the lobe's chi-square (m = 10 and m = 3) and of both region
// tests on the solution, every known bug of render/mis_known_bugs_a6.hpp through the check that
// catches it, and the efficiency ratio on the solution and on light sampling passed off as MIS.

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/a2/a2_checks.hpp"
#include "assignments/error_map.hpp"
#include "assignments/grading.hpp"
#include "assignments/subject/requests.hpp"
#include "integration/statistics.hpp"
#include "render/veach_plates.hpp"
#include "stats/chi_square.hpp"
#include "stats/hypothesis.hpp"
#include "stats/sampler_tests.hpp"

namespace mcrt::testing::assignment {

// ---------------------------------------------------------------- a6.1 the Phong lobe

/// The exponent of the chi-square and integral tests: lobe wide enough that the hemisphere's
/// equal-area cells resolve it (the top band holds 65% of the samples, the horizon's cells are
/// pooled), sharp enough that u^(1/m) for u^(1/(m+1)) moves the mean cosine by 30 standard
/// errors at 1e5 samples.
inline constexpr double k_a6_lobe_m = 10.0;

/// The lobe's local samples (round +z) and its pdf round +z, as check_sampler's batches.
template <class S>
auto lobe_samples_of(S& subject, double m) {
  return [&subject, m](const std::vector<Vec2>& u) { return subject.a6_lobe_samples(m, u); };
}
template <class S>
auto lobe_pdf_of(S& subject, double m, Vec3 reflected = {0.0, 0.0, 1.0}) {
  return [&subject, m, reflected](const std::vector<Vec3>& points) {
    return subject.a6_lobe_pdf(m, reflected, points);
  };
}

/// What the samples' shape says: below the horizon, half the azimuths, the exponent off by one.
inline std::string diagnose_lobe_samples(const std::vector<Vec3>& points, double m) {
  RunningStats cos_alpha;
  std::size_t below = 0, negative_y = 0, not_unit = 0;
  for (const Vec3& w : points) {
    cos_alpha.add(w.z);
    below += w.z < 0.0;
    negative_y += w.y < 0.0;
    not_unit += !(std::abs(glm::length(w) - 1.0) < 1e-9);
  }
  if (not_unit > 0)
    return diagnosis(
        fmt::format("{} directions are not unit vectors: is sin(alpha) = sqrt(1 - cos^2(alpha))?",
                    not_unit));
  if (below > 0)
    return diagnosis(fmt::format(
        "{} directions are below the lobe's horizon (z < 0 round +z): is cos(alpha) in [0, 1]?",
        below));
  const double n = static_cast<double>(points.size());
  // phi in [0, pi) puts no sample at y < 0; a uniform phi puts half there (sd 0.5 / sqrt(n))
  if (static_cast<double>(negative_y) < 0.25 * n)
    return diagnosis("almost no direction has y < 0: is phi = 2 pi u1 (the whole circle)?");
  // E[cos alpha] = (m + 1) / (m + 2) for the lobe, m / (m + 1) for c = u^(1/m)
  const double se = std::sqrt(cos_alpha.variance() / n);
  const double right = (m + 1.0) / (m + 2.0), off_by_one = m / (m + 1.0);
  if (std::abs(cos_alpha.mean() - off_by_one) < 4.0 * se &&
      std::abs(cos_alpha.mean() - right) > 8.0 * se)
    return diagnosis(fmt::format(
        "the mean cos(alpha) is {:.4f}, that of cos(alpha) = u^(1/m) ({:.4f}), not {:.4f}: the "
        "density of c = cos(alpha) is (m + 1) c^m, so its CDF is c^(m + 1): invert that",
        cos_alpha.mean(), off_by_one, right));
  if (cos_alpha.mean() < right - 8.0 * se)
    return diagnosis(fmt::format("the lobe is too wide (mean cos(alpha) {:.4f}, expected {:.4f})",
                                 cos_alpha.mean(), right));
  if (cos_alpha.mean() > right + 8.0 * se)
    return diagnosis(fmt::format("the lobe is too narrow (mean cos(alpha) {:.4f}, expected {:.4f})",
                                 cos_alpha.mean(), right));
  return "";
}

/// The lobe's samples at one seed of its chi-square: u from Rng(seed, 61).
template <class S>
std::vector<Vec3> lobe_samples_at(S& subject, double m, std::uint64_t seed) {
  Rng rng(seed, 61);
  std::vector<Vec2> u(k_sampler_samples);
  for (Vec2& x : u) x = rng.uniform2();
  return subject.a6_lobe_samples(m, u);
}

/// a6.1: the lobe's sampler against its pdf (chi-square at the grading seeds, u from
/// Rng(seed, 61)); on failure the heat map and a diagnosis.
template <class S>
TaskResult check_lobe_sampler(S&& subject, double m = k_a6_lobe_m) {
  const Binning<Vec3> binning = sampler_hemisphere_binning();
  const std::string name = "a6_phong_lobe";
  const std::vector<double> probability = bulk_cell_probabilities(lobe_pdf_of(subject, m), binning);
  std::string diagnosis_text;
  bool reported = false;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    const std::vector<Vec3> points = lobe_samples_at(subject, m, seed);
    const ChiSquareResult r = chi_square_points_test(points, probability, binning);
    if (r.p_value < k_seed_alpha && !reported) {
      reported = true;
      diagnosis_text = diagnose_lobe_samples(points, m);
      report_chi_square_failure({name, k_sampler_samples, 61, k_seed_alpha}, r, binning);
    }
    return r.p_value;
  });
  std::string message = fmt::format("Phong lobe m = {} chi-square: {}", m, v.describe());
  if (!v.passed()) {
    double total = 0.0;
    for (double p : probability) total += p;
    if (std::abs(total - 1.0) >= 1e-6)
      diagnosis_text = diagnosis(fmt::format(
          "your pdf integrates to {:.3f}, not 1, and this test compares your samples with it: fix the pdf first "
          "(its own test says how), then run this test again",
          total));
    message +=
        fmt::format("\nthe heat map of (observed - expected) / sqrt(expected) is in {}/{}/\n{}",
                    failure_report_root().string(), name, diagnosis_text);
  }
  return {v.passed(), message};
}

/// a6.1: the pdf round +z integrates to 1 over the hemisphere (it is 0 below it: cos alpha < 0).
template <class S>
TaskResult check_lobe_pdf_integral(S&& subject, double m = k_a6_lobe_m) {
  const double total = bulk_pdf_integral(lobe_pdf_of(subject, m), sampler_hemisphere_binning());
  const bool ok = std::abs(total - 1.0) < 1e-6;
  std::string message =
      fmt::format("phong_lobe_pdf at m = {} integrates to {:.6f} over the hemisphere round r", m,
                  total);
  if (!ok) {
    message += '\n';
    if (near(total, (m + 2.0) / (m + 1.0), 1e-4))
      message += diagnosis(
          "your pdf is (m + 2)/(m + 1) too large: (m + 2)/(2 pi) normalises the BRDF (with its "
          "cos(theta_i)); the lobe's pdf is (m + 1)/(2 pi) cos^m(alpha)");
    else if (near(total, 2.0 * k_pi / (m + 1.0), 1e-4))
      message +=
          diagnosis("your pdf integrates to 2 pi/(m + 1): the factor (m + 1)/(2 pi) is missing");
    else
      message += diagnosis(fmt::format("a pdf integrates to 1: yours is {:.3f}x too large", total));
  }
  return {ok, message};
}

/// a6.1: the pdf is a function of the angle to `reflected`, whichever way it points: at 10
/// directions round a tilted mirror direction, (m + 1)/(2 pi) cos^m(alpha) (relative 1e-9:
/// pow's round-off at m = 10 is 1e-15), 0 behind the lobe.
template <class S>
TaskResult check_lobe_pdf_round_mirror(S&& subject, double m = k_a6_lobe_m) {
  const Vec3 r = glm::normalize(Vec3(0.6, -0.3, 0.5));
  const Frame frame(r);
  std::vector<Vec3> points;
  std::vector<double> expected;
  for (double c : {1.0, 0.97, 0.8, 0.3, -0.2})
    for (double phi : {0.0, 2.5}) {
      if (c == 1.0 && phi != 0.0) continue;
      const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
      points.push_back(frame.to_world({s * std::cos(phi), s * std::sin(phi), c}));
      expected.push_back(c > 0.0 ? (m + 1.0) / (2.0 * k_pi) * std::pow(c, m) : 0.0);
    }
  points.push_back(-r);
  expected.push_back(0.0);
  const std::vector<double> got = subject.a6_lobe_pdf(m, r, points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double g = i < got.size() ? got[i] : std::nan("");
    if (!(std::abs(g - expected[i]) <= 1e-9 * expected[i] + 1e-300)) {
      std::string message = fmt::format(
          "phong_lobe_pdf round r = ({:.3f}, {:.3f}, {:.3f}) at w = ({:.3f}, {:.3f}, {:.3f}): "
          "{:.6g}, expected {:.6g}",
          r.x, r.y, r.z, points[i].x, points[i].y, points[i].z, g, expected[i]);
      const double from_z =
          points[i].z > 0.0 ? (m + 1.0) / (2.0 * k_pi) * std::pow(points[i].z, m) : 0.0;
      if (std::abs(g - from_z) <= 1e-9 * from_z + 1e-300)
        message +=
            '\n' + diagnosis(
                       "your pdf uses w.z, the angle to the normal: the lobe is round the mirror "
                       "direction, cos(alpha) = w . reflected");
      return {false, message};
    }
  }
  return {true, "phong_lobe_pdf follows cos(alpha) = w . reflected at 10 directions"};
}

/// a6.1: at m = 1e4 (a near mirror) sin(alpha) keeps its digits. For u0 near 1, 1 - cos(alpha)
/// is ~1e-13 and 1 - cos^2 computed from cos loses 3 of its digits; 1 - cos(alpha) =
/// -expm1(log(u0)/(m + 1)) does not. Relative 1e-6: the careful form is within 1e-14, the
/// cancelling one off by 1e-4 at u0 = 1 - 1e-9.
template <class S>
TaskResult check_sharp_lobe_digits(S&& subject) {
  constexpr double m = 1e4;
  const std::vector<Vec2> u{{1.0 - 1e-9, 0.3}, {0.999999, 0.7}, {0.9, 0.1}, {0.5, 0.55}};
  const std::vector<Vec3> w = subject.a6_lobe_samples(m, u);
  for (std::size_t i = 0; i < u.size(); ++i) {
    const long double one_minus_cos =
        -std::expm1(std::log(static_cast<long double>(u[i].x)) / (m + 1.0L));
    const long double sin_alpha = std::sqrt(one_minus_cos * (2.0L - one_minus_cos));
    const double got = i < w.size() ? std::sqrt(w[i].x * w[i].x + w[i].y * w[i].y) : std::nan("");
    const double length = i < w.size() ? glm::length(w[i]) : std::nan("");
    if (!(std::abs(length - 1.0) < 1e-12))
      return {false, fmt::format("m = 1e4, u = ({}, {}): the direction has length {:.15g}, not 1",
                                 u[i].x, u[i].y, length)};
    const double relative =
        std::abs(got - static_cast<double>(sin_alpha)) / static_cast<double>(sin_alpha);
    if (!(relative < 1e-6))
      return {
          false,
          fmt::format(
              "m = 1e4, u0 = {:.9f}: sin(alpha) = {:.10g}, exact {:.10g} (relative error {:.2g})\n{}",
              u[i].x, got, static_cast<double>(sin_alpha), relative,
              diagnosis("sin(alpha) lost its digits: 1 - cos^2(alpha) cancels when cos(alpha) "
                        "is within 1e-13 of 1; compute 1 - cos(alpha) directly "
                        "(-expm1(log(u0) / (m + 1))) and sin = sqrt((1 - c)(1 + c))"))};
  }
  return {true, "sin(alpha) within 1e-6 of exact at m = 1e4, u0 up to 1 - 1e-9"};
}

// ---------------------------------------------------------------- a6.2 the heuristics

/// Exact weights (p_s, p_o, balance, power): written as numbers, so the test holds no formula.
struct WeightCase {
  double p_s, p_o, balance, power;
};
inline constexpr std::array<WeightCase, 9> k_weight_cases{{
    {1.0, 3.0, 0.25, 0.1},
    {3.0, 1.0, 0.75, 0.9},
    {2.0, 2.0, 0.5, 0.5},
    {0.5, 0.0, 1.0, 1.0},
    {0.0, 7.0, 0.0, 0.0},
    {0.0, 0.0, 0.0, 0.0},  // a direction neither strategy draws: weight 0, not NaN
    {1.0, 4.0, 0.2, 1.0 / 17.0},
    {40.0, 10.0, 0.8, 16.0 / 17.0},
    {0.125, 0.375, 0.25, 0.1},
}};

/// a6.2: one heuristic against the table (relative 1e-15: a correct form rounds at most twice),
/// and w(a, b) + w(b, a) = 1 for 400 pairs spread over 12 decades.
template <class S>
TaskResult check_heuristic(S&& subject, A6Heuristic h) {
  const char* name = h == A6Heuristic::power ? "power_heuristic" : "balance_heuristic";
  std::vector<Vec2> pairs;
  for (const WeightCase& c : k_weight_cases) pairs.emplace_back(c.p_s, c.p_o);
  Rng rng(6, 2);
  for (int i = 0; i < 200; ++i) {
    const double a = std::pow(10.0, 12.0 * rng.uniform() - 6.0),
                 b = std::pow(10.0, 12.0 * rng.uniform() - 6.0);
    pairs.emplace_back(a, b);
    pairs.emplace_back(b, a);
  }
  const std::vector<double> w = subject.a6_weights(h, pairs);
  const auto at = [&](std::size_t i) { return i < w.size() ? w[i] : std::nan(""); };
  // First the sums (the property MIS's unbiasedness rests on), then the exact values.
  double worst = 0.0;
  std::size_t worst_i = k_weight_cases.size();
  for (std::size_t i = k_weight_cases.size(); i + 1 < pairs.size(); i += 2) {
    const double off = std::abs(at(i) + at(i + 1) - 1.0);
    if (!(off <= worst)) worst = off, worst_i = i;
  }
  // 1e-12: the two weights' round-off is a few ulps each
  if (!(worst <= 1e-12))
    return {false,
            fmt::format("{}: w({:.3g}, {:.3g}) + w({:.3g}, {:.3g}) = {:.6g}, not 1\n{}", name,
                        pairs[worst_i].x, pairs[worst_i].y, pairs[worst_i].y, pairs[worst_i].x,
                        at(worst_i) + at(worst_i + 1),
                        diagnosis(
                            "the weights of one direction must sum to 1 (w_s + w_o = 1), or MIS is "
                            "biased: divide p_s (or p_s^2) by the sum over both strategies"))};
  for (std::size_t i = 0; i < k_weight_cases.size(); ++i) {
    const WeightCase& c = k_weight_cases[i];
    const double expected = h == A6Heuristic::power ? c.power : c.balance;
    if (!(std::abs(at(i) - expected) <= 1e-15 * expected)) {
      std::string message = fmt::format("{}(p_s = {}, p_o = {}) = {:.17g}, expected {:.17g}", name,
                                        c.p_s, c.p_o, at(i), expected);
      if (std::isnan(at(i)))
        message +=
            '\n' +
            diagnosis(
                "a weight is NaN: when both pdfs are 0 (a direction neither strategy can draw) "
                "the weight is 0: guard the division");
      else if (h == A6Heuristic::power && std::abs(at(i) - c.balance) <= 1e-15 * c.balance)
        message +=
            '\n' +
            diagnosis(
                "your power heuristic gives the balance heuristic's weights: square both pdfs "
                "(p_s^2 / (p_s^2 + p_o^2))");
      else if (h == A6Heuristic::balance && std::abs(at(i) - c.power) <= 1e-15 * c.power)
        message +=
            '\n' + diagnosis(
                       "your balance heuristic gives the power heuristic's weights: the balance "
                       "heuristic is p_s / (p_s + p_o), the pdfs not squared");
      return {false, message};
    }
  }
  return {true, fmt::format("{}: the table's {} exact weights, and 200 pairs sum to 1", name,
                            k_weight_cases.size())};
}

// ---------------------------------------------------------------- a6.3 MIS on the plates

/// spp of the student's renders: 256 per pixel puts 4000-11500 samples in each region. At 64
/// the sharpest plate's smallest light (plate 3, light 0: a relative variance of 45 per sample,
/// heavy-tailed) made the z-test reject the solution at 5e-4 in 3 of 400 runs; at 256 none of
/// 300 (measured, seeds 200001-200150, both heuristics: Sidak p below 0.05 in 4.0%, below 0.01
/// in 0.7%).
inline constexpr int k_a6_spp = 256;

/// The reference: each region's mean and its standard error, from the instructor's MIS (power
/// heuristic) at 16384 spp of a6_region_samples on 96 x 72 pixels, seed 0x5eed6 (none of the
/// grading seeds). The largest standard error is 1.5% of its mean (plate 3, light 0). Printed by
/// diagnosis_test.cpp's DISABLED_A6PrintReference (instructor tree only).
struct RegionReference {
  double mean, standard_error;
};
inline constexpr std::array<RegionReference, 16> k_a6_reference{{
    {0.040938114068471018, 3.2615867379422958e-05},  // plate 0, light 0: 45 pixels
    {0.060330696809732166, 2.861996270106114e-05},   // plate 0, light 1: 27 pixels
    {0.060091413514883944, 2.8439536547329661e-05},  // plate 0, light 2: 27 pixels
    {0.040541133833433537, 3.1791346794324846e-05},  // plate 0, light 3: 45 pixels
    {0.16916117766343622, 0.00046908555980089477},   // plate 1, light 0: 24 pixels
    {0.25323244518402321, 0.00059683822408146642},   // plate 1, light 1: 18 pixels
    {0.25327594454624724, 0.00057313077544026607},   // plate 1, light 2: 18 pixels
    {0.1450025427647974, 0.00026664795792352372},    // plate 1, light 3: 24 pixels
    {0.71054684446747218, 0.003970022921319722},     // plate 2, light 0: 20 pixels
    {0.88262103698323402, 0.0047009506934868129},    // plate 2, light 1: 16 pixels
    {0.78052924144677827, 0.0026603729089766256},    // plate 2, light 2: 16 pixels
    {0.33104091954307485, 0.00034379888903155912},   // plate 2, light 3: 20 pixels
    {1.4405015795153413, 0.021915487992911424},      // plate 3, light 0: 16 pixels
    {1.4679596458535367, 0.013096735855919485},      // plate 3, light 1: 16 pixels
    {1.1853136062287701, 0.0037480984972079528},     // plate 3, light 2: 16 pixels
    {0.44788207398768881, 0.00019866328879614544},   // plate 3, light 3: 16 pixels
}};

/// Per-region statistics of samples listed as a6_region_samples lists them; a missing value is
/// NaN (and fails the region).
inline std::vector<RunningStats> a6_region_stats(const std::vector<double>& values, int spp) {
  std::vector<RunningStats> stats;
  std::size_t i = 0;
  for (const PlateRegion& r : plate_regions(make_veach_plates(), k_a6_width, k_a6_height)) {
    RunningStats s;
    for (long k = 0; k < static_cast<long>(r.pixel_count()) * spp; ++k, ++i)
      s.add(i < values.size() ? values[i] : std::nan(""));
    stats.push_back(s);
  }
  return stats;
}

/// The regions where one strategy wins by far (measured, 16384 spp): light sampling on the
/// rough plate with the smallest light, BSDF sampling on the sharpest plate with the largest.
inline constexpr std::size_t k_a6_light_region = 0;  // plate 0 (m = 10), light 0 (r = 0.03)
inline constexpr std::size_t k_a6_bsdf_region = 15;  // plate 3 (m = 1e4), light 3 (r = 0.9)

/// The ratio of a region's mean to the reference's.
inline double region_ratio(const std::vector<RunningStats>& s, std::size_t r) {
  return s[r].mean() / k_a6_reference[r].mean;
}

/// The shape of a biased MIS: which strategy's regions are off says which weight is wrong.
inline std::string diagnose_mis_regions(const std::vector<RunningStats>& s) {
  const double light = region_ratio(s, k_a6_light_region), bsdf = region_ratio(s, k_a6_bsdf_region);
  double low = 1.0, high = 1.0;
  for (std::size_t r = 0; r < s.size(); ++r)
    low = std::min(low, region_ratio(s, r)), high = std::max(high, region_ratio(s, r));
  const auto text = [&](const char* what) {
    return diagnosis(fmt::format(
        "{} (where light sampling wins: {:.2f}x the reference; where BSDF sampling wins: {:.2f}x)",
        what, light, bsdf));
  };
  if (!std::isfinite(light) || !std::isfinite(bsdf))
    return diagnosis("a region's mean is not finite: a division by a pdf of 0?");
  // Measured with the known-wrong variants of diagnosis_test.cpp (64 spp, the first failing
  // seed): a BSDF sample weighted by w(p_l, p_b) gives 1.14-1.42x and 0.02x, one added with
  // weight 1 1.14-1.42x and 1.00x, a light sample added with weight 1 1.01x and 1.92x, p_l per
  // unit area 150x and 1.01x. Region 0's mean has a standard error of about 1.3%: 1.08 is six.
  if (light > 1.08 && bsdf < 0.5)
    return text(
        "the BSDF sample is weighted as if it were the light sample: its weight is w(p_b, p_l), not w(p_l, p_b)");
  if (light < 0.5 && bsdf > 1.08)
    return text(
        "the light sample is weighted as if it were the BSDF sample: its weight is w(p_l, p_b), not w(p_b, p_l)");
  if (high > 8.0 || low < 0.05)
    return text(
        "some regions are off by a large factor: are both pdfs of a weight in the same measure? p_l must be "
        "per steradian (p_A r^2 / cos(theta_y), with the 1/N of picking the light), as p_b is; a p_A per unit "
        "area is ~r^2 / cos(theta_y) times smaller");
  if (light > 1.08 && near(bsdf, 1.0, 0.05))
    return text(
        "light is counted twice where light sampling wins: the BSDF sample that hits a light is added with "
        "weight 1; weight it by w_b = w(p_b, p_l), so that w_l + w_b = 1");
  if (near(light, 1.0, 0.05) && bsdf > 1.08)
    return text(
        "light is counted twice where BSDF sampling wins: the light sample is added with weight 1; weight it "
        "by w_l = w(p_l, p_b), so that w_l + w_b = 1");
  return text(
      "the weights of a direction must sum to 1 (w_l(w) + w_b(w) = 1 for every w), each the heuristic of its "
      "own strategy's pdf against the other's, both per steradian");
}

/// One seed of the region test: the Sidak-combined p-value of the 16 regions' z-tests against
/// the reference (standard error from the region's samples and the reference's own); each
/// region's signed z in `z`, in plate_regions's order, when given.
inline double mis_regions_p_value(const std::vector<RunningStats>& s, std::size_t& worst,
                                  double& worst_z, std::vector<double>* signed_z = nullptr) {
  double p_min = 1.0;
  for (std::size_t r = 0; r < s.size(); ++r) {
    const double n = static_cast<double>(s[r].count());
    const double se = std::sqrt(s[r].variance() / n + k_a6_reference[r].standard_error *
                                                          k_a6_reference[r].standard_error);
    const double p = z_test_p_value(s[r].mean(), k_a6_reference[r].mean, se);
    if (signed_z != nullptr) signed_z->push_back(region_z(s[r].mean(), k_a6_reference[r].mean, se));
    if (!(p >= p_min)) {
      p_min = p;
      const double z = std::abs(s[r].mean() - k_a6_reference[r].mean) / se;
      if (!(z <= worst_z)) worst_z = z, worst = r;
    }
  }
  return sidak_p_value(p_min, static_cast<int>(s.size()));
}

/// The 16 regions' statistics of one seed's render by MIS with `heuristic`.
template <class S>
std::vector<RunningStats> mis_region_stats_at(S& subject, A6Strategy heuristic,
                                              std::uint64_t seed) {
  return a6_region_stats(subject.a6_regions(heuristic, k_a6_width, k_a6_height, k_a6_spp, seed),
                         k_a6_spp);
}

/// The error map of the plates: a row per plate (sharpest last), a column per light (largest
/// last), as plate_regions lists them.
inline RegionErrorMap make_plates_error_map() {
  std::vector<std::string> columns, rows;
  for (int i = 0; i < 4; ++i) {
    columns.push_back(fmt::format("light r={}", k_plate_light_radii[static_cast<std::size_t>(i)]));
    rows.push_back(fmt::format("plate m={}", k_plate_exponents[static_cast<std::size_t>(i)]));
  }
  return make_error_map(4, 4, columns, rows);
}

/// a6.3: MIS with `heuristic` agrees with the reference in every region, at the grading seeds.
template <class S>
RegionResult check_mis_regions(S&& subject, A6Strategy heuristic) {
  std::size_t worst = 0;
  double worst_z = 0.0;
  std::vector<RunningStats> failed;
  RegionResult result;
  result.map = make_plates_error_map();
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    const std::vector<RunningStats> s = mis_region_stats_at(subject, heuristic, seed);
    std::vector<double> z;
    const double p = mis_regions_p_value(s, worst, worst_z, &z);
    add_seed(result.map, z);
    if (p < k_seed_alpha && failed.empty()) failed = s;
    return p;
  });
  const char* name = heuristic == A6Strategy::mis_power ? "power" : "balance";
  std::string message = fmt::format(
      "MIS ({} heuristic) on Veach's plates, {} x {}, {} spp, 16 plate x light regions: {}", name,
      k_a6_width, k_a6_height, k_a6_spp, v.describe());
  const auto done = [&](bool passed) {
    static_cast<TaskResult&>(result) = {passed, message};
    return result;
  };
  if (v.passed()) return done(true);
  const PlateRegion r = plate_regions(make_veach_plates(), k_a6_width, k_a6_height)[worst];
  message += fmt::format(
      "\nthe worst region, plate {} (m = {}) x light {} (radius {}), is {:.1f} standard errors from the "
      "reference\n{}",
      r.plate, k_plate_exponents[r.plate], r.light, k_plate_light_radii[r.light], worst_z,
      diagnose_mis_regions(failed));
  return done(false);
}

/// The variance per camera sample of the two single strategies at equal rays (light or BSDF
/// sampling, two samples a plate point: the rays of MIS's one of each), per region: the
/// instructor's chapter 08 code at 16384 spp (seeds 0x5eed7, 0x5eed8). Stored, not measured at
/// grading: a single strategy's sample variance at 256 spp is itself heavy-tailed (BSDF
/// sampling on the rough plate finds the small light once in ~500 samples) and would make the
/// ratio below noisy.
struct StrategyVariances {
  double light, bsdf;
};
inline constexpr std::array<StrategyVariances, 16> k_a6_single_strategy_variance{{
    {0.000430171, 4.26238},   // plate 0, light 0
    {0.000183507, 2.47716},   // plate 0, light 1
    {0.000183436, 2.36412},   // plate 0, light 2
    {0.000422745, 0.589545},  // plate 0, light 3
    {0.0465052, 29.8985},     // plate 1, light 0
    {0.0527801, 8.23177},     // plate 1, light 1
    {0.0523722, 0.896313},    // plate 1, light 2
    {0.0349262, 0.0497037},   // plate 1, light 3
    {3.06042, 139.423},       // plate 2, light 0
    {3.6809, 15.7575},        // plate 2, light 1
    {2.95322, 1.51899},       // plate 2, light 2
    {1.07994, 0.0261288},     // plate 2, light 3
    {92.7774, 322.148},       // plate 3, light 0
    {86.2116, 37.1409},       // plate 3, light 1
    {64.0357, 3.218},         // plate 3, light 2
    {21.918, 0.00751597},     // plate 3, light 3
}};

/// The factor by which MIS's variance may exceed the better single strategy's in a region at
/// equal rays. Measured with the solution (256 spp, seeds 300001-300150): the largest ratio
/// over the 16 regions is 2.55 (median) to 2.69 (max) with the balance heuristic, 2.0-2.14
/// with the power heuristic (plate 0, light 2: light sampling's two samples beat MIS's one
/// where BSDF sampling adds nothing). 4 leaves room for the sample variance's noise, while
/// light sampling passed off as MIS exceeds it ~5000x (plate 3, light 3: diagnosis_test.cpp).
inline constexpr double k_a6_variance_factor = 4.0;

/// One seed of the efficiency test: the largest ratio over the regions of MIS's sample
/// variance to the better single strategy's, and where it is.
template <class S>
double mis_variance_ratio(S&& subject, A6Strategy heuristic, std::uint64_t seed,
                          std::size_t& where) {
  const std::vector<RunningStats> mis = mis_region_stats_at(subject, heuristic, seed);
  double worst = 0.0;
  for (std::size_t r = 0; r < mis.size(); ++r) {
    const StrategyVariances& v = k_a6_single_strategy_variance[r];
    const double ratio = mis[r].variance() / std::min(v.light, v.bsdf);
    if (!(ratio <= worst)) worst = ratio, where = r;
  }
  return worst;
}

/// a6.3: at equal rays MIS's variance is within k_a6_variance_factor of the better single
/// strategy's in every region, at 2 of the 3 grading seeds.
template <class S>
TaskResult check_mis_efficiency(S&& subject, A6Strategy heuristic) {
  std::array<double, k_seeds> ratios{};
  std::array<std::size_t, k_seeds> where{};
  int failures = 0;
  for (int i = 0; i < k_seeds; ++i) {
    ratios[i] = mis_variance_ratio(subject, heuristic, k_grading_seeds[i], where[i]);
    failures += !(ratios[i] <= k_a6_variance_factor);
  }
  std::string message = fmt::format(
      "the largest ratio of MIS's variance to the better single strategy's at equal rays, "
      "over the 16 regions: {:.3g}, {:.3g}, {:.3g} at the 3 seeds (at most {} passes)",
      ratios[0], ratios[1], ratios[2], k_a6_variance_factor);
  if (failures < 2) return {true, message};
  const std::size_t r = where[0];
  message +=
      '\n' +
      diagnosis(fmt::format(
          "in region plate {} x light {} MIS is {:.0f}x noisier than the better strategy alone: each sample's weight must "
          "fall where its own strategy's f Le cos / p is large (p small): w_s = heuristic(p_s, p_other), both pdfs per "
          "steradian (a p_A per unit area for p_l leaves the light sample almost no weight)",
          r / 4, r % 4, ratios[0]));
  return {false, message};
}

}  // namespace mcrt::testing::assignment
