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
#include "sampling/owen_scramble.hpp"
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

/// Dimension 1 of Sobol' points (direction numbers all 1: Pascal's triangle mod 2) has the
/// columns c_0 = 2^31, c_b = c_(b-1) xor (c_(b-1) >> 1). Stored bit-reversed here, so the
/// reversed bits of a point's y, which Owen scrambling works on, are xors of these;
/// tests/sampling/path_sampler_test.cpp checks them against Boost's (sobol_matrices.hpp).
inline constexpr std::array<std::uint32_t, 32> k_sobol_dimension1_reversed = [] {
  std::array<std::uint32_t, 32> columns{};
  std::uint32_t c = 0x80000000u;
  for (unsigned b = 0; b < 32; ++b, c ^= c >> 1) columns[b] = reverse_bits(c);
  return columns;
}();

/// The same columns summed four index bits at a time: entry [k][v] is the xor of the columns
/// 4k + j for the bits j set in v, so a 2^m-point set's y takes ceil(m / 4) lookups, no branch.
inline constexpr std::array<std::array<std::uint32_t, 16>, 8> k_sobol_dimension1_nibbles = [] {
  std::array<std::array<std::uint32_t, 16>, 8> sums{};
  for (unsigned k = 0; k < 8; ++k)
    for (unsigned v = 0; v < 16; ++v)
      for (unsigned j = 0; j < 4; ++j)
        if ((v >> j) & 1u) sums[k][v] ^= k_sobol_dimension1_reversed[4 * k + j];
  return sums;
}();

/// Dimension 1 of Sobol' point p, bit-reversed, for p < 2^(4 nibbles).
inline std::uint32_t sobol_dimension1_reversed(std::uint32_t p, unsigned nibbles) {
  std::uint32_t y = 0;
  for (unsigned k = 0; k < nibbles; ++k) y ^= k_sobol_dimension1_nibbles[k][(p >> (4 * k)) & 15u];
  return y;
}

/// reverse_bits of each 32-bit half of w, both at once (reverse_bits' swaps on 64 bits, all but
/// the last, which would exchange the halves).
constexpr std::uint64_t reverse_bits_of_halves(std::uint64_t w) {
  w = ((w >> 1) & 0x5555555555555555ull) | ((w & 0x5555555555555555ull) << 1);
  w = ((w >> 2) & 0x3333333333333333ull) | ((w & 0x3333333333333333ull) << 2);
  w = ((w >> 4) & 0x0f0f0f0f0f0f0f0full) | ((w & 0x0f0f0f0f0f0f0f0full) << 4);
  w = ((w >> 8) & 0x00ff00ff00ff00ffull) | ((w & 0x00ff00ff00ff00ffull) << 8);
  return ((w >> 16) & 0x0000ffff0000ffffull) | ((w & 0x0000ffff0000ffffull) << 16);
}

/// What a 2D set of a pixel needs whatever the sample, made once per pixel: its key (jittered:
/// its permutation of the cells; both: the low bits of each sample) and, for Sobol' sets, the
/// two Owen scrambles and the four rounds of the sample shuffle.
/// No initialisers: a pixel's cache of them is left unwritten until a sample reaches a set.
struct PaddedSetKeys {
  std::uint64_t key;
  std::uint32_t seed_x, seed_y;          ///< sobol: the coordinates' Owen scrambles
  std::uint32_t round_a[3], round_b[3];  ///< sobol: the shuffle's round functions
};

/// The key of 2D set `set` (0: the pixel position, 1 + b: bounce b) of pixel_key's pixel.
inline std::uint64_t padded_set_key(std::uint64_t pixel_key, unsigned set) {
  return mix64(pixel_key + (set + std::uint64_t{1}) * k_stream_offset);
}

/// Set `set`'s keys (each mix64, SplitMix64's finaliser, of the set's key stepped by the
/// golden-ratio constant): jittered needs the key only, sobol also its scrambles and rounds.
inline PaddedSetKeys padded_set_keys(PathSampler kind, std::uint64_t pixel_key, unsigned set) {
  PaddedSetKeys keys{};
  keys.key = padded_set_key(pixel_key, set);
  if (kind != PathSampler::sobol) return keys;
  const std::uint64_t seeds = mix64(keys.key);
  keys.seed_x = static_cast<std::uint32_t>(seeds);
  keys.seed_y = static_cast<std::uint32_t>(seeds >> 32);
  for (unsigned r = 0; r < 3; ++r) {
    const std::uint64_t round = mix64(keys.key + (r + std::uint64_t{2}) * k_stream_offset);
    keys.round_a[r] = static_cast<std::uint32_t>(round);
    keys.round_b[r] = static_cast<std::uint32_t>(round >> 32);
  }
  return keys;
}

/// The half width h of the sample shuffle's words for n samples: the least h with 2^(2h) >= n.
inline unsigned shuffle_half_bits(std::uint32_t n) {
  unsigned h = 1;
  while ((std::uint64_t{1} << (2 * h)) < n) ++h;
  return h;
}

/// Where sample i goes under the random permutation of {0, ..., n-1} of a set (n >= 2, h =
/// shuffle_half_bits(n)): a three-round Feistel network on 2h bits, round r's function
/// F_r(v) = ((a_r v + b_r) mod 2^32) >> (32 - h), walked back into [0, n) (see permutation.hpp).
/// With a_r, b_r uniform, F_r is Dietzfelbinger's multiply-add-shift hash, pairwise independent
/// for inputs of at most 32 - h bits (v has h <= 16). Three rounds of random functions make a
/// permutation that queries of its forward direction, which is all a pairing of samples is,
/// cannot tell from a random one (Luby and Rackoff); the pairing test below checks ours, at a
/// multiply per round. The lighter
/// permutation_element keeps enough of the index's low bits that two sets' first Sobol'
/// digits, which are those bits, stay correlated; an Owen-scrambled index keeps the pairs
/// {2k, 2k+1} together, with the same effect.
inline std::uint32_t shuffled_sample(std::uint32_t i, std::uint32_t n, unsigned h,
                                     const PaddedSetKeys& keys) {
  const std::uint32_t mask = (std::uint32_t{1} << h) - 1;
  std::uint32_t x = i;
  do {
    std::uint32_t left = x >> h, right = x & mask;
    for (unsigned r = 0; r < 3; ++r) {
      const std::uint32_t f = (keys.round_a[r] * right + keys.round_b[r]) >> (32 - h);
      const std::uint32_t next = left ^ f;
      left = right;
      right = next;
    }
    x = left << h | right;
  } while (x >= n);
  return x;
}

/// A pixel's padded sets: its key, its sample count and the keys of its first k_cached_sets
/// sets, each made when a sample first reaches it and then shared by every sample of the pixel
/// (a Sobol' set's keys cost five mix64; a sample's point in it, at most one). A value on the stack of the
/// pixel loop, no allocation: sets beyond the cache are made per sample, the same bits.
class PaddedPixel {
 public:
  static constexpr unsigned k_cached_sets = 32;

  /// `pixel_key` names the pixel's randomisation (pixel_key below); kind is not independent.
  PaddedPixel(PathSampler kind, std::uint64_t pixel_key, std::uint32_t count)
      : kind_(kind),
        pixel_key_(pixel_key),
        count_(count),
        half_bits_(shuffle_half_bits(count)),
        index_nibbles_((2 * half_bits_ + 3) / 4),
        columns_(kind == PathSampler::jittered ? JitteredPoints::grid_columns(count) : 1) {}

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
    const PaddedSetKeys& keys = set(set_index);
    if (kind_ == PathSampler::sobol) {
      // Dimensions 0 and 1 of Sobol' point pi(index), each Owen-scrambled by the set's seeds:
      // a (0,m,2)-net at count = 2^m, each point uniform. pi, a random permutation of the
      // samples per set (shuffled_sample; pbrt-v4's padded Sobol' sampler has one), pairs the
      // sets at random: without it the scrambles of two sets would keep the sample order's
      // nesting, and bounce b's first digit would equal bounce b''s, flipped or not, for every
      // sample. Owen scrambling works on reversed bits (owen_scramble.hpp): dimension 0, the
      // radical inverse, is the index reversed, so its reversed bits are the index itself.
      const std::uint32_t p = count_ <= 1 ? 0 : shuffled_sample(index, count_, half_bits_, keys);
      const std::uint32_t y_reversed = sobol_dimension1_reversed(p, index_nibbles_);
      const std::uint64_t xy =
          reverse_bits_of_halves(std::uint64_t{laine_karras_permutation(p, keys.seed_x)} << 32 |
                                 laine_karras_permutation(y_reversed, keys.seed_y));
      const auto x = static_cast<std::uint32_t>(xy >> 32), y = static_cast<std::uint32_t>(xy);
      // The bits below the 32 scrambled ones, so a point is uniform in double precision: a
      // 2^-32 refinement no estimate can resolve, so one multiply-xorshift of (key, index)
      // serves (uniform over the keys; each half of the word a different refinement).
      std::uint64_t low_bits = (keys.key ^ index) * k_mix64_first;
      low_bits ^= low_bits >> 29;
      const double low_x = static_cast<std::uint32_t>(low_bits >> 32) * 0x1p-32;
      const double low_y = static_cast<std::uint32_t>(low_bits) * 0x1p-32;
      return {(x + low_x) * 0x1p-32, (y + low_y) * 0x1p-32};
    }
    // Jittered: the sample's cell of the columns x rows grid, by the set's permutation, and
    // the place in the cell from one mix64 of (key, index).
    const std::uint64_t low_bits = mix64(keys.key ^ (index + std::uint64_t{1}) * k_stream_offset);
    const double low_x = static_cast<std::uint32_t>(low_bits) * 0x1p-32;
    const double low_y = static_cast<std::uint32_t>(low_bits >> 32) * 0x1p-32;
    const std::uint32_t cell = permutation_element(index, count_, keys.key);
    const std::uint32_t rows = count_ / columns_;
    return {(cell % columns_ + low_x) / columns_, (cell / columns_ + low_y) / rows};
  }

 private:
  PathSampler kind_;
  std::uint64_t pixel_key_;
  std::uint32_t count_;
  unsigned half_bits_;      // of the Sobol' sample shuffle
  unsigned index_nibbles_;  // a shuffled index is below 2^(2 half_bits_) <= 16^index_nibbles_
  std::uint32_t columns_;   // of the jittered grid: the largest divisor of count <= sqrt(count)
  unsigned made_ = 0;       // sets_[0, made_) are made
  std::array<PaddedSetKeys, k_cached_sets> sets_;
  PaddedSetKeys beyond_{};
};

/// Sample `index` of a pixel's samples, as padded 2D sets: each uniform2() is the sample's
/// point in the next set. A small value, made per sample: no allocation, no virtual call; the
/// estimator takes it where it would take an Rng (uniform2() and uniform()). Per bounce:
/// jittered, a mix64 and a permutation element; sobol, three multiply-add rounds of the
/// shuffle, one Sobol' column sum, two Laine-Karras hashes and a multiply for the low bits (the
/// set's keys are the pixel's, made once).
class PaddedSample {
 public:
  PaddedSample(PaddedPixel& pixel, std::uint32_t index) : pixel_(&pixel), index_(index) {}

  /// This sample's point in the next 2D set.
  Vec2 uniform2() { return pixel_->point(index_, set_++); }

  /// A single uniform (a delta material's choice): the first coordinate of the next set, so
  /// every bounce takes one set whatever it samples.
  double uniform() { return uniform2().x; }

  /// Sets drawn so far (1 + the bounces that sampled a direction).
  unsigned sets_drawn() const { return set_; }

 private:
  PaddedPixel* pixel_;
  std::uint32_t index_;
  unsigned set_ = 0;
};

}  // namespace mcrt
