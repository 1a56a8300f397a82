#pragma once
// Two renders of one image compared region by region: every block of b x b pixels, every row,
// every column and the image's border ring. A bias that lives in a few pixels of one edge (a
// row whose rays start somewhere else, a corner) is diluted in a block that also holds bright,
// noisy pixels, but stands out in its row, its column, the border or the corner block; a
// bias spread thinly over the image stands out in the blocks and the large regions.
//
// Per region and channel: d = sum over its pixels of (mean_a - mean_b), v = the sum of both
// pixels' variances of the mean (renders independent, pixels independent), z = d / sqrt(v),
// standard normal when both are unbiased for the same image (CLT: thousands of samples per
// pixel). Two-sided z-tests, Sidak over every region and channel. The statistics overlap
// (a pixel is in a block, a row, a column and maybe the border) and a region's channels are
// correlated; for two-sided tests of jointly normal statistics Sidak's inequality makes the
// Sidak level conservative whatever the correlation, so the family-wise false-failure rate is
// at most alpha.

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/render.hpp"
#include "stats/hypothesis.hpp"
#include "support/color_moments.hpp"

namespace mcrt::testing {

/// The pixel indices (y * width + x) of each region: the blocks (the last ones cut at the
/// image's edge), then the rows, the columns, and the border ring.
inline std::vector<std::vector<std::size_t>> comparison_regions(int width, int height, int block) {
  std::vector<std::vector<std::size_t>> regions;
  const auto index = [&](int x, int y) { return static_cast<std::size_t>(y * width + x); };
  for (int by = 0; by < height; by += block)
    for (int bx = 0; bx < width; bx += block) {
      std::vector<std::size_t>& r = regions.emplace_back();
      for (int y = by; y < std::min(height, by + block); ++y)
        for (int x = bx; x < std::min(width, bx + block); ++x) r.push_back(index(x, y));
    }
  for (int y = 0; y < height; ++y) {
    std::vector<std::size_t>& r = regions.emplace_back();
    for (int x = 0; x < width; ++x) r.push_back(index(x, y));
  }
  for (int x = 0; x < width; ++x) {
    std::vector<std::size_t>& r = regions.emplace_back();
    for (int y = 0; y < height; ++y) r.push_back(index(x, y));
  }
  std::vector<std::size_t>& border = regions.emplace_back();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (x == 0 || y == 0 || x == width - 1 || y == height - 1) border.push_back(index(x, y));
  return regions;
}

/// The per-pixel moments of both renders of a comparison, sample by sample: the project's
/// (render/render.hpp run once per sample index s, spp 1, so every pixel value is one sample
/// and its spread is measured) and the reference's `reference(x, y, rng)` for pixel (x, y),
/// drawn from streams (2^20 + pixel, s), which the project's render never uses.
struct PairedMoments {
  std::vector<ColorMoments> ours, reference;
};
template <class Estimate, class Reference>
PairedMoments paired_pixel_moments(const Camera& camera, int width, int height, int samples,
                                   std::uint64_t seed, Estimate&& estimate, Reference&& reference) {
  const auto pixels = static_cast<std::size_t>(width * height);
  PairedMoments m{std::vector<ColorMoments>(pixels), std::vector<ColorMoments>(pixels)};
  for (int s = 0; s < samples; ++s) {
    const RenderSettings settings{1, static_cast<std::uint64_t>(s), seed, 1, nullptr};
    const Image image = render(camera, settings, estimate).image;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const auto p = static_cast<std::size_t>(y * width + x);
        m.ours[p].add(image.at(x, y));
        Rng rng(seed, stream_index((std::uint64_t{1} << 20) + p, static_cast<std::uint64_t>(s)));
        m.reference[p].add(reference(x, y, rng));
      }
  }
  return m;
}

/// The worst region of a comparison, for a failure's message.
struct RegionVerdict {
  double p_value = 1.0;   ///< Sidak-combined over every region and channel
  std::size_t worst = 0;  ///< the region of the smallest p-value (comparison_regions order)
  double worst_z = 0.0;   ///< its z (a's mean above b's: positive)
};

/// The Sidak-combined p-value of a against b (per-pixel moments of two renders of one image).
inline RegionVerdict region_agreement(const std::vector<ColorMoments>& a,
                                      const std::vector<ColorMoments>& b, int width, int height,
                                      int block) {
  std::vector<double> p_values;
  RegionVerdict verdict;
  double smallest = 2.0;
  const std::vector<std::vector<std::size_t>> regions = comparison_regions(width, height, block);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    Vec3 d(0.0), variance(0.0);
    for (const std::size_t p : regions[r]) {
      d += a[p].mean() - b[p].mean();
      const glm::dmat3 s = a[p].covariance_of_mean() + b[p].covariance_of_mean();
      variance += Vec3(s[0][0], s[1][1], s[2][2]);
    }
    for (int k = 0; k < 3; ++k) {
      // A channel with no spread in either render must agree exactly.
      const double p = variance[k] > 0.0 ? z_test_p_value(d[k], 0.0, std::sqrt(variance[k]))
                                         : (d[k] == 0.0 ? 1.0 : 0.0);
      p_values.push_back(p);
      if (p < smallest) {
        smallest = p;
        verdict.worst = r;
        verdict.worst_z = variance[k] > 0.0 ? d[k] / std::sqrt(variance[k]) : 0.0;
      }
    }
  }
  verdict.p_value = sidak_p_value(p_values);
  return verdict;
}

}  // namespace mcrt::testing
