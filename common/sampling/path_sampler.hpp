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

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/math.hpp"
#include "sampling/padded_sobol.hpp"
#include "sampling/padded_sobol_block.hpp"
#include "sampling/permutation.hpp"
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

/// Set `set`'s keys: jittered needs the key only, sobol also its scrambles and rounds.
inline PaddedSetKeys padded_set_keys(PathSampler kind, std::uint64_t pixel_key, unsigned set) {
  PaddedSetKeys keys{};
  keys.key = padded_set_key(pixel_key, set);
  if (kind == PathSampler::sobol) make_sobol_set_keys(keys);
  return keys;
}

/// A pixel's padded sets: its key, its sample count, the keys of its first k_cached_sets sets,
/// each made when a sample first reaches it and then shared by every sample of the pixel (a
/// Sobol' set's keys cost five mix64), and for Sobol' sets the points of the current block of
/// k_sobol_block samples, made together (padded_sobol_block.hpp) when the first sample of the
/// block reaches the set. A value on the stack of the pixel loop, no allocation: sets beyond
/// the cache are made per sample, the same bits.
class PaddedPixel {
 public:
  static constexpr unsigned k_cached_sets = 32;

  /// `pixel_key` names the pixel's randomisation (pixel_key below); kind is not independent.
  PaddedPixel(PathSampler kind, std::uint64_t pixel_key, std::uint32_t count)
      : kind_(kind),
        pixel_key_(pixel_key),
        count_(count),
        half_bits_(shuffle_half_bits(count)),
        columns_(kind == PathSampler::jittered ? JitteredPoints::grid_columns(count) : 1) {
    block_of_.fill(k_no_block);
  }

  /// The seed's randomisation of pixel `pixel` for the samples from `first_sample` on: two
  /// renders with different first samples (chapter 05's pair A, B) are independent.
  static std::uint64_t pixel_key(std::uint64_t seed, std::uint64_t pixel,
                                 std::uint64_t first_sample) {
    return hash_bits(seed, pixel, first_sample);
  }

  /// The keys of set `set`, made once.
  const PaddedSetKeys& set(unsigned set) {
    if (set >= k_cached_sets) {
      beyond_ = padded_set_keys(kind_, pixel_key_, set);
      return beyond_;
    }
    for (; made_ <= set; ++made_) sets_[made_] = padded_set_keys(kind_, pixel_key_, made_);
    return sets_[set];
  }

  /// Sample `index`'s point in set `set`.
  Vec2 point(std::uint32_t index, unsigned set_index) {
    if (kind_ == PathSampler::sobol) return sobol_point(index, set_index);
    // Jittered: the sample's cell of the columns x rows grid, by the set's permutation, and
    // the place in the cell from one mix64 of (key, index).
    const PaddedSetKeys& keys = set(set_index);
    const std::uint64_t low_bits = mix64(keys.key ^ (index + std::uint64_t{1}) * k_stream_offset);
    const double low_x = static_cast<std::uint32_t>(low_bits) * 0x1p-32;
    const double low_y = static_cast<std::uint32_t>(low_bits >> 32) * 0x1p-32;
    const std::uint32_t cell = permutation_element(index, count_, keys.key);
    const std::uint32_t rows = count_ / columns_;
    return {(cell % columns_ + low_x) / columns_, (cell / columns_ + low_y) / rows};
  }

 private:
  static constexpr std::uint32_t k_no_block = ~std::uint32_t{0};

  /// padded_sobol_point(set's keys, index, count, h), read from the block of the set's points
  /// that holds it; a cached set's points are made a block at a time, the same bits.
  Vec2 sobol_point(std::uint32_t index, unsigned set_index) {
    if (set_index >= k_cached_sets)
      return padded_sobol_point(set(set_index), index, count_, half_bits_);
    const std::uint32_t block = index / k_sobol_block;
    if (block_of_[set_index] != block) {
      padded_sobol_block(set(set_index), block * k_sobol_block, count_, half_bits_,
                         points_[set_index]);
      block_of_[set_index] = block;
    }
    return points_[set_index][index % k_sobol_block];
  }

  PathSampler kind_;
  std::uint64_t pixel_key_;
  std::uint32_t count_;
  unsigned half_bits_;     // of the Sobol' sample shuffle
  std::uint32_t columns_;  // of the jittered grid: the largest divisor of count <= sqrt(count)
  unsigned made_ = 0;      // sets_[0, made_) are made
  std::array<PaddedSetKeys, k_cached_sets> sets_;
  PaddedSetKeys beyond_{};
  std::array<std::uint32_t, k_cached_sets> block_of_;  // sobol: points_[set]'s block, or none
  std::array<std::array<Vec2, k_sobol_block>, k_cached_sets> points_;
};

/// Sample `index` of a pixel's samples, as padded 2D sets: each uniform2() is the sample's
/// point in the next set. A small value, made per sample: no allocation, no virtual call; the
/// estimator takes it where it would take an Rng (uniform2() and uniform()). It makes each
/// point one set ahead, when the previous one is taken: the point does not depend on the path,
/// so the processor makes it while the path's ray is traced, off the path's chain of steps.
class PaddedSample {
 public:
  PaddedSample(PaddedPixel& pixel, std::uint32_t index)
      : pixel_(&pixel), index_(index), next_(pixel.point(index, 0)) {}

  /// This sample's point in the next 2D set.
  Vec2 uniform2() {
    const Vec2 point = next_;
    next_ = pixel_->point(index_, ++set_);
    return point;
  }

  /// A single uniform (a delta material's choice): the first coordinate of the next set, so
  /// every bounce takes one set whatever it samples.
  double uniform() { return uniform2().x; }

  /// Sets drawn so far (1 + the bounces that sampled a direction).
  unsigned sets_drawn() const { return set_; }

 private:
  PaddedPixel* pixel_;
  std::uint32_t index_;
  unsigned set_ = 0;  // the set of next_
  Vec2 next_;         // the point the next uniform2() returns
};

}  // namespace mcrt
