// The blocks of a padded Sobol' set (sampling/padded_sobol_block.hpp): the portable, AVX2,
// AVX-512 and dispatched versions, and a pixel's cache of blocks read in any order, give the
// plain point's bits (padded_sobol_point) at every sample count, block and order.

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/cpu_features.hpp"
#include "core/math.hpp"
#include "sampling/padded_sobol.hpp"
#include "sampling/padded_sobol_block.hpp"
#include "sampling/path_sampler.hpp"

using namespace mcrt;

namespace {

// Every count from 1 to 300 (walking or not, a last block full or partial) and the powers of
// four up to 4096, three sets' keys, every block: each version's point is the plain one's, bit
// for bit. The AVX2 and AVX-512 copies run only where the processor has them.
TEST(PaddedSobolBlockTest, BlocksGiveThePlainPointsAtEveryCount) {
  using BlockFunction = void (*)(const PaddedSetKeys&, std::uint32_t, std::uint32_t, unsigned,
                                 std::array<Vec2, k_sobol_block>&);
  std::vector<BlockFunction> versions = {padded_sobol_block_portable, padded_sobol_block};
  if (cpu_has_avx2()) versions.push_back(padded_sobol_block_avx2);
  if (cpu_has_avx512()) versions.push_back(padded_sobol_block_avx512);
  std::vector<std::uint32_t> counts(300);
  std::iota(counts.begin(), counts.end(), 1u);
  for (std::uint32_t count : {1024u, 4096u}) counts.push_back(count);
  for (std::uint32_t count : counts)
    for (unsigned set : {0u, 1u, 9u}) {
      const PaddedSetKeys keys = padded_set_keys(PathSampler::sobol, 1000 + count, set);
      const unsigned h = shuffle_half_bits(count);
      for (std::uint32_t first = 0; first < count; first += k_sobol_block)
        for (std::size_t v = 0; v < versions.size(); ++v) {
          std::array<Vec2, k_sobol_block> points{};
          versions[v](keys, first, count, h, points);
          for (std::uint32_t i = 0; i < k_sobol_block && first + i < count; ++i)
            ASSERT_EQ(points[i], padded_sobol_point(keys, first + i, count, h))
                << "version " << v << " count " << count << " set " << set << " sample "
                << first + i;
        }
    }
}

// A pixel's cached blocks, read in any order of samples and sets (a block made, left, made
// again), give the plain points: 37 samples (three blocks, the last partial), in a shuffled
// order.
TEST(PaddedSobolBlockTest, APixelsBlocksGiveThePlainPointsInAnyOrder) {
  constexpr std::uint32_t count = 37;
  std::vector<std::pair<std::uint32_t, unsigned>> visits;
  for (std::uint32_t s = 0; s < count; ++s)
    for (unsigned set = 0; set < 40; ++set) visits.emplace_back(s, set);
  std::shuffle(visits.begin(), visits.end(), std::mt19937(7));
  PaddedPixel pixel(PathSampler::sobol, 42, count);
  for (const auto& [s, set] : visits)
    ASSERT_EQ(pixel.point(s, set), padded_sobol_point(padded_set_keys(PathSampler::sobol, 42, set),
                                                      s, count, shuffle_half_bits(count)))
        << "sample " << s << " set " << set;
}

}  // namespace
