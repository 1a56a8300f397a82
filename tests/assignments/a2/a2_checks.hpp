#pragma once
// The grading procedures of assignment a2 (sampling directions), templated on the sampler and
// pdf under test so that tests/assignments/diagnosis_test.cpp can run them on wrong variants.
// Each sampler is held to the chi-square test of tests/stats/ (about 230 equal-measure cells,
// 1e5 points) at three seeds, failing on 2 of 3 rejections at 5e-4 (grading.hpp), and its pdf
// must integrate to 1 over its domain (Gauss-Kronrod per cell, tolerance 1e-6).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/grading.hpp"
#include "stats/binning.hpp"
#include "stats/chi_square.hpp"
#include "stats/report.hpp"
#include "stats/sampler_tests.hpp"

namespace mcrt::testing::assignment {

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

enum class SamplerKind { uniform_hemisphere, cosine_hemisphere, uniform_sphere, unit_disk };

/// The shape of the observed / expected ratios says which distribution the samples follow.
inline std::string diagnose_sampler(SamplerKind kind, const ChiSquareResult& r, const Grid& grid) {
  const bool disk = kind == SamplerKind::unit_disk;
  const std::vector<double> ratio = band_ratios(r, disk ? grid.u_cells : grid.v_cells, disk);
  if (r.outside > 0)
    return diagnosis(fmt::format("{} samples fell outside the domain (not unit length, below the horizon, or outside the disk)", r.outside));
  switch (kind) {
    case SamplerKind::uniform_hemisphere:
      if (bands_follow(ratio, 0.0, 1.0, [](double c) { return 2.0 * c; }))
        return diagnosis("observed/expected ~ 2 cos(theta): your samples look cosine-distributed, not uniform");
      if (ratio.back() > 1.5 && ratio.front() < 0.5)
        return diagnosis("too many samples near the pole: is cos(theta) drawn as sqrt(u) or is theta = pi/2 u uniform in angle?");
      break;
    case SamplerKind::cosine_hemisphere:
      if (bands_follow(ratio, 0.0, 1.0, [](double c) { return 0.5 / c; }))
        return diagnosis("observed/expected ~ 1 / (2 cos(theta)): your samples look uniform on the hemisphere, not cosine-weighted");
      // r = u0: observed/expected = 1 / (2 sqrt(1 - cos^2)), 0.5 at the horizon, 2.3 in the top band
      if (ratio.front() > 0.4 && ratio.front() < 0.65 && ratio.back() > 1.5)
        return diagnosis("half the expected samples near the horizon and too many near the pole: is the disk point "
                         "at r = u0 instead of r = sqrt(u0) before you lift it to the hemisphere?");
      break;
    case SamplerKind::uniform_sphere:
      if (ratio.front() < 0.05 && ratio.back() > 1.5)
        return diagnosis("no samples below the equator: is z drawn in [0, 1] instead of [-1, 1]?");
      break;
    case SamplerKind::unit_disk:
      if (ratio.front() > 1.5 && ratio.back() < 0.8)
        return diagnosis("points crowd the centre: is r = u instead of sqrt(u)?");
      break;
  }
  return "";
}

/// A sampler's chi-square test at the grading seeds; on failure, the heat map's path (written
/// under test-reports/, or $MCRT_TEST_REPORT_DIR) and a diagnosis.
template <class Point, class Sampler, class Pdf>
TaskResult check_sampler(const Sampler& sample, const Pdf& pdf, const Binning<Point>& binning,
                         SamplerKind kind, const std::string& name) {
  std::string diagnosis_text;
  bool reported = false;
  const SeedVerdict v = at_grading_seeds([&](std::uint64_t seed) {
    const ChiSquareResult r =
        chi_square_sampler_test(sample, pdf, binning, seed, k_sampler_samples, 41);
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
    const double total = pdf_integral(pdf, binning);
    if (std::abs(total - 1.0) >= 1e-6)
      diagnosis_text = diagnosis(fmt::format(
          "your pdf integrates to {:.3f}, not 1, and this test compares your samples with it: fix the pdf "
          "first (its own test says how), then run this test again", total));
    message += fmt::format("\nthe heat map of (observed - expected) / sqrt(expected) is in {}/{}/\n{}",
                           failure_report_root().string(), name, diagnosis_text);
  }
  return {v.passed(), message};
}

/// The pdf integrates to 1 over the binning's domain.
template <class Point, class Pdf>
TaskResult check_pdf_integral(const Pdf& pdf, const Binning<Point>& binning, const std::string& name) {
  const double total = pdf_integral(pdf, binning);
  const bool ok = std::abs(total - 1.0) < 1e-6;
  std::string message = fmt::format("{} integrates to {:.6f} over its domain", name, total);
  if (!ok) {
    message += '\n';  // appended alone: "\n" + a temporary trips a false -Wrestrict in g++ 12
    message += diagnosis(fmt::format("a pdf integrates to 1: yours is {:.3f}x too large{}", total,
                                     near(total, 2.0, 0.01) ? " (is it off by a factor of 2: 1/pi vs 1/(2 pi)?)" : ""));
  }
  return {ok, message};
}

}  // namespace mcrt::testing::assignment
