// The 16 generator lanes of the disk engine (core/pcg32_lanes.hpp): each lane is pcg-cpp's
// pcg32, seeded from an Rng with a seed and a stream of its own.

#include <gtest/gtest.h>

#include <cstdint>

#include <pcg_random.hpp>

#include "core/pcg32_lanes.hpp"
#include "core/rng.hpp"

using namespace mcrt;

namespace {

TEST(Pcg32LanesTest, EachLaneIsTheLibrarysPcg32) {
  Pcg32Lanes<4> lanes;
  for (int l = 0; l < 4; ++l) lanes.seed_lane(l, 42 + l, 1000 * l + 7);
  for (int l = 0; l < 4; ++l) {
    pcg32 reference(42 + l, 1000 * l + 7);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(lanes.next(l), reference()) << "lane " << l;
  }
}

TEST(Pcg32LanesTest, SeededFromAnRngDrawsSeedAndStreamPerLane) {
  Rng rng(5, 6), copy(5, 6);
  Pcg32Lanes<16> lanes;
  lanes.seed_from(rng);
  for (int l = 0; l < 16; ++l) {
    const std::uint64_t seed = (std::uint64_t{copy.next_bits()} << 32) | copy.next_bits();
    const std::uint64_t stream = (std::uint64_t{copy.next_bits()} << 32) | copy.next_bits();
    pcg32 reference(seed, stream);
    for (int i = 0; i < 10; ++i) ASSERT_EQ(lanes.next(l), reference()) << "lane " << l;
  }
}

}  // namespace
