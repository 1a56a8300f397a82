#pragma once
/// The uniforms of one path, drawn from a point set rather than a stream: --sampler.
///
/// A path needs a 2D point for its pixel position and one per bounce for its direction. With
/// `independent` they come from the pixel sample's Rng stream (render/render.hpp). With
/// `jittered` or `sobol`, the spp samples of a pixel are the points of 2D sets, one set per
/// use ("padding", as pbrt-v4's padded Sobol' sampler does): set 0 places the samples in the
/// pixel, set 1 + b gives bounce b its direction. Sample s of the pixel is point s of every set,
/// and each set is randomised by a key of its own (seed, pixel, first sample, set), so:
///   - within a set the spp points are stratified (one per cell, or a (0,m,2)-net at spp = 2^m);
///   - across sets the pairing of points is random, so bounce b's direction does not correlate
///     with the pixel position or with bounce b' (a d-dimensional net would need d dimensions
///     of Sobol' matrices; padding needs only the first two and never runs out);
///   - each point alone is uniform on [0,1)^2 (the sets are randomised), so the path's estimate
///     keeps the expectation of the independent one: unbiased.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/math.hpp"
#include "sampling/point_random.hpp"
#include "sampling/point_sets.hpp"

namespace mcrt {

/// Where a path's uniforms come from.
enum class PathSampler {
  independent,  ///< the pixel sample's own random stream (the default, as before)
  jittered,     ///< one sample in each cell of a near-square grid of spp cells, per 2D set
  sobol,        ///< Owen-scrambled Sobol' points (dimensions 0 and 1), per 2D set
};

inline constexpr PathSampler k_path_samplers[] = {PathSampler::independent, PathSampler::jittered,
                                                  PathSampler::sobol};

/// The sampler's name on the command line: independent, jittered or sobol.
inline std::string name_of(PathSampler sampler) {
  const char* names[] = {"independent", "jittered", "sobol"};
  return names[static_cast<int>(sampler)];
}

/// The sampler named `name`, if there is one.
inline std::optional<PathSampler> path_sampler_named(std::string_view name) {
  for (PathSampler sampler : k_path_samplers)
    if (name == name_of(sampler)) return sampler;
  return std::nullopt;
}

/// Where sample i goes under the random permutation of {0, ..., n-1} named by key: a four-round
/// Feistel network on 2h bits (2^(2h) >= n, each round's function a mix64 of the key, the
/// round and the other half), walked back into [0, n) (see permutation.hpp). Four rounds of
/// random functions make a permutation no test of the pairing can tell from a random one
/// (Luby and Rackoff); the lighter permutation_element keeps enough of the index's low bits
/// that two sets' first Sobol' digits, which are those bits, stay correlated.
inline std::uint32_t shuffled_sample(std::uint32_t i, std::uint32_t n, std::uint64_t key) {
  if (n <= 1) return 0;
  unsigned h = 1;
  while ((std::uint64_t{1} << (2 * h)) < n) ++h;
  const std::uint64_t mask = (std::uint64_t{1} << h) - 1;
  std::uint64_t x = i;
  do {
    std::uint64_t left = x >> h, right = x & mask;
    for (std::uint64_t round = 1; round <= 4; ++round) {
      const std::uint64_t f = mix64((key + round * k_stream_offset) ^ right) & mask;
      const std::uint64_t next = left ^ f;
      left = right;
      right = next;
    }
    x = left << h | right;
  } while (x >= n);
  return static_cast<std::uint32_t>(x);
}

/// Sample `index` of a pixel's `count` samples, as padded 2D sets: each uniform2() is the
/// sample's point in the next set. A small value, made per sample: no allocation, no virtual
/// call; the estimator takes it where it would take an Rng (uniform2() and uniform()).
///
/// The sets are those of point_sets.hpp, drawn two coordinates at once and with fewer hashes
/// (each mix64, SplitMix64's finaliser, of a key stepped by the golden-ratio constant): the
/// set's key, its two scrambles from one mix64 of it, and both coordinates' low bits from one
/// mix64 of (key, index) (Sobol': the bits below the 32 scrambled ones; jittered: the place
/// within the cell). Per bounce: three mix64 and a permutation element (jittered: of the
/// cells; sobol: of the samples, four more mix64, then two Owen scrambles and one Sobol'
/// column sum).
class PaddedSample {
 public:
  /// `pixel_key` names the pixel's randomisation (pixel_key below); kind is not independent.
  PaddedSample(PathSampler kind, std::uint64_t pixel_key, std::uint32_t count, std::uint32_t index)
      : kind_(kind),
        pixel_key_(pixel_key),
        count_(count),
        index_(index),
        columns_(kind == PathSampler::jittered ? JitteredPoints::grid_columns(count) : 1) {}

  /// The seed's randomisation of pixel `pixel` for the samples from `first_sample` on: two
  /// renders with different first samples (chapter 05's pair A, B) are independent.
  static std::uint64_t pixel_key(std::uint64_t seed, std::uint64_t pixel,
                                 std::uint64_t first_sample) {
    return hash_bits(seed, pixel, first_sample);
  }

  /// The key of 2D set `set` (0: the pixel position, 1 + b: bounce b), its own scramble.
  static std::uint64_t set_key(std::uint64_t pixel_key, unsigned set) {
    return mix64(pixel_key + (set + std::uint64_t{1}) * k_stream_offset);
  }

  /// This sample's point in the next 2D set.
  Vec2 uniform2() {
    const std::uint64_t key = set_key(pixel_key_, set_++);
    const std::uint64_t low_bits = mix64(key ^ (index_ + std::uint64_t{1}) * k_stream_offset);
    const double low_x = static_cast<std::uint32_t>(low_bits) * 0x1p-32;
    const double low_y = static_cast<std::uint32_t>(low_bits >> 32) * 0x1p-32;
    if (kind_ == PathSampler::sobol) {
      // Dimensions 0 and 1 of Sobol' point pi(index), each Owen-scrambled by half of
      // mix64(key): a (0,m,2)-net at count = 2^m, each point uniform. pi, a random permutation
      // of the samples per set (shuffled_sample; pbrt-v4's padded Sobol' sampler has one), pairs the sets at
      // random: without it the scrambles of two sets would keep the sample order's nesting, and
      // bounce b's first digit would equal bounce b''s, flipped or not, for every sample.
      // Dimension 0 is the radical inverse in base 2: the index's bits reversed.
      const std::uint32_t point = shuffled_sample(index_, count_, key);
      const std::uint64_t seeds = mix64(key);
      const auto x = owen_scramble(reverse_bits(point), static_cast<std::uint32_t>(seeds));
      const auto y = owen_scramble(sobol_bits(point, 1), static_cast<std::uint32_t>(seeds >> 32));
      return {(x + low_x) * 0x1p-32, (y + low_y) * 0x1p-32};
    }
    // Jittered: the sample's cell of the columns x rows grid, by the set's permutation.
    const std::uint32_t cell = permutation_element(index_, count_, key);
    const std::uint32_t rows = count_ / columns_;
    return {(cell % columns_ + low_x) / columns_, (cell / columns_ + low_y) / rows};
  }

  /// A single uniform (a delta material's choice): the first coordinate of the next set, so
  /// every bounce takes one set whatever it samples.
  double uniform() { return uniform2().x; }

  /// Sets drawn so far (1 + the bounces that sampled a direction).
  unsigned sets_drawn() const { return set_; }

 private:
  PathSampler kind_;
  std::uint64_t pixel_key_;
  std::uint32_t count_, index_;
  std::uint32_t columns_;  // of the jittered grid: the largest divisor of count <= sqrt(count)
  unsigned set_ = 0;
};

}  // namespace mcrt
