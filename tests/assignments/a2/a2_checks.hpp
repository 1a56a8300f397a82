#pragma once
// The grading procedures of assignment a2 (sampling directions). Each judges what a bulk
// producer returns: `samples(us)` the sampler's points for a vector of u, `pdf(points)` the
// pdf's values at a vector of points. The tests take them from subject() (the student's code,
// in-process or in the subject program); tests/assignments/diagnosis_test.cpp from known-wrong
// variants through each().
// Each sampler is held to the chi-square test of tests/stats/ (about 230 equal-measure cells,
// 1e5 points) at three seeds, failing on 2 of 3 rejections at 5e-4 (grading.hpp), and its pdf
// must integrate to 1 over its domain (Gauss-Kronrod per cell, tolerance 1e-6).

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>
#include <vector>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/grading.hpp"
#include "assignments/subject/requests.hpp"
#include "stats/binning.hpp"
#include "stats/chi_square.hpp"
#include "stats/report.hpp"
#include "stats/sampler_tests.hpp"

namespace mcrt::testing::assignment {

namespace detail {
// The cone of a2.5 (k_a2_cone_cos_theta_max) on (phi, cos theta) cells, as the hemisphere's: a
// direction below the cone's rim, by more than round-off, is outside the domain.
inline std::optional<Vec2> cone_parameters(const Vec3& w) {
  const std::optional<Vec2> uv = testing::detail::hemisphere_parameters(w);
  if (!uv || uv->y < k_a2_cone_cos_theta_max - testing::detail::k_domain_slack) return std::nullopt;
  return uv;
}
}  // namespace detail

/// a2.5's cone, 21 phi by 11 cos(theta) cells of equal solid angle (odd counts, as the
/// hemisphere's: sampler_hemisphere_binning).
inline Binning<Vec3> sampler_cone_binning() {
  return {{"cone (phi, cos theta)", "phi (rad)", "cos(theta)", 0.0, k_two_pi,
           k_a2_cone_cos_theta_max, 1.0, 21, 11, 1.0},
          &testing::detail::hemisphere_point,
          &detail::cone_parameters};
}

/// Observed / expected per band of the radial parameter (cos theta or z: the v cells of the
/// hemisphere and sphere binnings; r^2: the u cells of the disk binning), summed over phi.
inline std::vector<double> band_ratios(const ChiSquareResult& r, int bands, bool radial_is_u) {
  std::vector<double> observed(static_cast<std::size_t>(bands)), expected(observed.size());
  for (const CellCount& c : r.cells) {
    const auto band = static_cast<std::size_t>(radial_is_u ? c.u_index : c.v_index);
    observed[band] += c.observed;
    expected[band] += c.expected;
  }
  for (std::size_t j = 0; j < observed.size(); ++j) observed[j] /= std::max(expected[j], 1e-300);
  return observed;
}

/// Whether ratio[j] stays within 12% of shape(band centre j) in every band.
template <class Shape>
bool bands_follow(const std::vector<double>& ratio, double low, double high, Shape&& shape) {
  const double width = (high - low) / static_cast<double>(ratio.size());
  for (std::size_t j = 0; j < ratio.size(); ++j) {
    const double s = shape(low + (static_cast<double>(j) + 0.5) * width);
    if (std::abs(ratio[j] - s) > 0.12 * s) return false;
  }
  return true;
}

/// Whether ratio[j] stays within 12% of band_mean(low_j, high_j), the shape's exact mean over
/// band j (for a shape too steep to take at the band's centre).
template <class BandMean>
bool bands_match(const std::vector<double>& ratio, double low, double high, BandMean&& band_mean) {
  const double width = (high - low) / static_cast<double>(ratio.size());
  for (std::size_t j = 0; j < ratio.size(); ++j) {
    const double a = low + static_cast<double>(j) * width, s = band_mean(a, a + width);
    if (std::abs(ratio[j] - s) > 0.12 * s) return false;
  }
  return true;
}

/// theta uniform in angle, cos(theta) = c: observed / expected = 2 / (pi sqrt(1 - c^2)) against
/// any density uniform in c, whose mean over [c0, c1] is (2/pi) (asin c1 - asin c0) / (c1 - c0).
inline double uniform_in_angle_band_mean(double c0, double c1) {
  return 2.0 / k_pi * (std::asin(std::min(c1, 1.0)) - std::asin(std::max(c0, -1.0))) / (c1 - c0);
}

/// The shape of the observed / expected ratios says which distribution the samples follow.
inline std::string diagnose_sampler(SamplerKind kind, const ChiSquareResult& r, const Grid& grid) {
  const bool disk = kind == SamplerKind::unit_disk;
  const std::vector<double> ratio = band_ratios(r, disk ? grid.u_cells : grid.v_cells, disk);
  if (kind == SamplerKind::uniform_cone && r.outside > 0)
    return diagnosis(fmt::format(
        "{} directions fell outside the cone: cos(theta) must stay within [cos(theta_max), 1] "
        "(u0 cos(theta_max), say, runs from 0 to cos(theta_max): below the cone)",
        r.outside));
  if (r.outside > 0)
    return diagnosis(fmt::format(
        "{} samples fell outside the domain (not unit length, below the horizon, or outside the disk)",
        r.outside));
  switch (kind) {
    case SamplerKind::uniform_hemisphere:
      if (bands_follow(ratio, 0.0, 1.0, [](double c) { return 2.0 * c; }))
        return diagnosis(
            "observed/expected ~ 2 cos(theta): your samples look cosine-distributed, not uniform");
      if (bands_match(ratio, 0.0, 1.0, uniform_in_angle_band_mean))
        return diagnosis(
            "observed/expected ~ 2 / (pi sin(theta)), in every band of cos(theta): your directions are "
            "uniform in the angle theta (theta = pi/2 u0), not in solid angle. The area of a zone of the "
            "hemisphere is linear in cos(theta): uniform in solid angle means cos(theta) uniform");
      if (ratio.back() > 1.5 && ratio.front() < 0.5)
        return diagnosis("too many samples near the pole: is cos(theta) drawn as sqrt(u)?");
      break;
    case SamplerKind::cosine_hemisphere:
      if (bands_follow(ratio, 0.0, 1.0, [](double c) { return 0.5 / c; }))
        return diagnosis(
            "observed/expected ~ 1 / (2 cos(theta)): your samples look uniform on the hemisphere, not cosine-weighted");
      // r = u0: observed/expected = 1 / (2 sqrt(1 - cos^2)), 0.5 at the horizon, 2.3 in the top band
      if (ratio.front() > 0.4 && ratio.front() < 0.65 && ratio.back() > 1.5)
        return diagnosis(
            "half the expected samples near the horizon and too many near the pole: is the disk point "
            "at r = u0 instead of r = sqrt(u0) before you lift it to the hemisphere?");
      break;
    case SamplerKind::uniform_sphere:
      if (ratio.front() < 0.05 && ratio.back() > 1.5)
        return diagnosis("no samples below the equator: is z drawn in [0, 1] instead of [-1, 1]?");
      if (bands_match(ratio, -1.0, 1.0, uniform_in_angle_band_mean))
        return diagnosis(
            "observed/expected ~ 2 / (pi sin(theta)), in every band of z: your directions are uniform in "
            "the angle theta (theta = pi u0), not in solid angle, and crowd both poles. The area of a zone "
            "of the sphere is linear in z: uniform in solid angle means z uniform");
      break;
    case SamplerKind::unit_disk:
      if (ratio.front() > 1.5 && ratio.back() < 0.8)
        return diagnosis("points crowd the centre: is r = u instead of sqrt(u)?");
      break;
    case SamplerKind::uniform_cone:
      // theta = u0 theta_max: the density per steradian grows as 1 / sin(theta) towards the axis
      if (ratio.back() > 1.3 && ratio.front() < 0.95)
        return diagnosis(
            "too many directions near the axis: is theta drawn uniform in angle (theta = u0 theta_max)? "
            "Uniform in solid angle means uniform in cos(theta)");
      break;
  }
  return "";
}

/// The cell probabilities of a pdf known only through bulk requests, exactly as
/// cell_probabilities computes them: the adaptive quadrature runs on the values known so far
/// (0 for a point not yet asked), the points it lacked are asked in one request, and it runs
/// again until it lacked none. Every round asks at least the first point the final run needs,
/// so it ends; a pdf smooth in each cell takes a few rounds.
template <class Point, class PdfBatch>
std::vector<double> bulk_cell_probabilities(PdfBatch&& pdf, const Binning<Point>& binning) {
  struct Key {
    Point p;
    bool operator==(const Key& o) const { return std::memcmp(&p, &o.p, sizeof p) == 0; }
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      std::size_t h = 0;
      const auto* words = reinterpret_cast<const std::uint64_t*>(&k.p);
      for (std::size_t i = 0; i < sizeof k.p / 8; ++i) h = (h ^ words[i]) * 0x100000001b3ULL;
      return h;
    }
  };
  std::unordered_map<Key, double, Hash> known;
  {
    // First the nodes of the quadrature's first level in every cell, as it computes them
    // (scale * t + mean): a pdf smooth in each cell needs no other, so one request and one run.
    using Quadrature = boost::math::quadrature::gauss_kronrod<double, 15>;
    const auto nodes = [](double a, double b) {
      const double mean = (b + a) / 2, scale = (b - a) / 2;
      std::vector<double> x;
      for (double t : Quadrature::abscissa()) {
        x.push_back(scale * t + mean);
        if (t != 0.0) x.push_back(scale * -t + mean);
      }
      return x;
    };
    std::vector<Point> first;
    for (int j = 0; j < binning.v_cells; ++j)
      for (int i = 0; i < binning.u_cells; ++i) {
        const double u0 = binning.u_low(i), v0 = binning.v_low(j);
        for (double v : nodes(v0, v0 + binning.v_width()))
          for (double u : nodes(u0, u0 + binning.u_width()))
            first.push_back(binning.point_at(u, v));
      }
    const std::vector<double> values = pdf(first);
    for (std::size_t i = 0; i < first.size(); ++i)
      known[Key{first[i]}] = i < values.size() ? values[i] : 0.0;
  }
  for (;;) {
    std::vector<Point> missing;
    std::unordered_map<Key, bool, Hash> asked;
    const auto lookup = [&](const Point& x) {
      const auto it = known.find(Key{x});
      if (it != known.end()) return it->second;
      if (asked.emplace(Key{x}, true).second) missing.push_back(x);
      return 0.0;
    };
    std::vector<double> probability = cell_probabilities(lookup, binning);
    if (missing.empty()) return probability;
    const std::vector<double> values = pdf(missing);
    for (std::size_t i = 0; i < missing.size(); ++i)
      known[Key{missing[i]}] = i < values.size() ? values[i] : 0.0;
  }
}

/// The integral of a bulk pdf over the binning's domain (pdf_integral's).
template <class Point, class PdfBatch>
double bulk_pdf_integral(PdfBatch&& pdf, const Binning<Point>& binning) {
  double total = 0.0;
  for (double p : bulk_cell_probabilities(pdf, binning)) total += p;
  return total;
}

/// A sampler's chi-square test at one seed: 1e5 points of u drawn from Rng(seed, 41), binned
/// against the cell probabilities of its pdf (bulk_cell_probabilities).
template <class Point, class SampleBatch>
ChiSquareResult sampler_chi_square(SampleBatch&& samples, const std::vector<double>& probability,
                                   const Binning<Point>& binning, std::uint64_t seed) {
  Rng rng(seed, 41);
  std::vector<Vec2> u(k_sampler_samples);
  for (Vec2& x : u) x = rng.uniform2();
  return chi_square_points_test(samples(u), probability, binning);
}

/// A sampler's chi-square test (sampler_chi_square) at the grading seeds; on failure, the heat
/// map's path (written under test-reports/, or $MCRT_TEST_REPORT_DIR) and a diagnosis.
template <class Point, class SampleBatch, class PdfBatch>
TaskResult check_sampler(SampleBatch&& samples, PdfBatch&& pdf, const Binning<Point>& binning,
                         SamplerKind kind, const std::string& name) {
  std::string diagnosis_text;
  bool reported = false;
  const std::vector<double> probability = bulk_cell_probabilities(pdf, binning);
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    const ChiSquareResult r = sampler_chi_square(samples, probability, binning, seed);
    if (r.p_value < k_seed_alpha && !reported) {
      reported = true;
      diagnosis_text = diagnose_sampler(kind, r, binning);
      report_chi_square_failure({name, k_sampler_samples, 41, k_seed_alpha}, r, binning);
    }
    return r.p_value;
  });
  std::string message = fmt::format("{} chi-square: {}", name, v.describe());
  if (!v.passed()) {
    // The test compares the samples with the pdf given: a pdf that is not a density fails a
    // correct sampler too, and its own test says how it is wrong.
    double total = 0.0;
    for (double p : probability) total += p;
    if (std::abs(total - 1.0) >= 1e-6)
      diagnosis_text = diagnosis(fmt::format(
          "your pdf integrates to {:.3f}, not 1, and this test compares your samples with it: fix the pdf "
          "first (its own test says how), then run this test again",
          total));
    message +=
        fmt::format("\nthe heat map of (observed - expected) / sqrt(expected) is in {}/{}/\n{}",
                    failure_report_root().string(), name, diagnosis_text);
  }
  return {v.passed(), message};
}

/// The bulk producers of a Subject for sampler `kind`, as check_sampler takes them: points of
/// type Point (a disk point as Vec2).
template <class Point, class S>
auto samples_of(S& subject, SamplerKind kind) {
  return [&subject, kind](const std::vector<Vec2>& u) {
    std::vector<Point> out;
    out.reserve(u.size());
    for (const Vec3& p : subject.samples(kind, u)) {
      if constexpr (std::is_same_v<Point, Vec2>)
        out.emplace_back(p.x, p.y);
      else
        out.push_back(p);
    }
    return out;
  };
}

template <class Point, class S>
auto pdf_of(S& subject, SamplerKind kind) {
  return [&subject, kind](const std::vector<Point>& points) {
    std::vector<Vec3> at;
    at.reserve(points.size());
    for (const Point& p : points) {
      if constexpr (std::is_same_v<Point, Vec2>)
        at.emplace_back(p.x, p.y, 0.0);
      else
        at.push_back(p);
    }
    return subject.pdf_values(kind, at);
  };
}

/// The pdf integrates to 1 over the binning's domain.
template <class Point, class PdfBatch>
TaskResult check_pdf_integral(PdfBatch&& pdf, const Binning<Point>& binning,
                              const std::string& name) {
  const double total = bulk_pdf_integral(pdf, binning);
  const bool ok = std::abs(total - 1.0) < 1e-6;
  std::string message = fmt::format("{} integrates to {:.6f} over its domain", name, total);
  if (!ok) {
    message += '\n';  // appended alone: "\n" + a temporary trips a false -Wrestrict in g++ 12
    const char* hint = near(total, 2.0, 0.01) ? " (is it off by a factor of 2: 1/pi vs 1/(2 pi)?)"
                       : near(total, k_two_pi, 0.01)
                           ? " (is the 2 pi of the full turn in phi missing?)"
                           : "";
    message +=
        diagnosis(fmt::format("a pdf integrates to 1: yours is {:.3f}x too large{}", total, hint));
  }
  return {ok, message};
}

}  // namespace mcrt::testing::assignment
