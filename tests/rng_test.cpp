// Generator streams: reproducible, distinct, in range. (Their distribution is checked by the
// statistical checks in tests/checks/rng_checks.cpp.)

#include <set>

#include <gtest/gtest.h>

#include "core/parallel.hpp"
#include "core/rng.hpp"
#include "integration/log_grid.hpp"

using namespace mcrt;

namespace {

TEST(RngTest, SameSeedAndStreamGiveTheSameSequence) {
  Rng a(42, 7), b(42, 7);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.next_bits(), b.next_bits());
}

TEST(RngTest, DifferentStreamsOrSeedsGiveDifferentSequences) {
  std::set<std::uint32_t> firsts;
  for (std::uint64_t stream = 0; stream < 100; ++stream) {
    Rng rng(42, stream);
    firsts.insert(rng.next_bits());
  }
  EXPECT_EQ(firsts.size(), 100u);  // 32-bit collisions among 100 values: chance ~1e-6
  Rng a(1, 0), b(2, 0);
  int equal = 0;
  for (int i = 0; i < 100; ++i) equal += a.next_bits() == b.next_bits();
  EXPECT_LT(equal, 2);
}

TEST(RngTest, UniformIsInTheHalfOpenUnitInterval) {
  Rng rng(3, 3);
  for (int i = 0; i < 100000; ++i) {
    const double u = rng.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
  }
  for (int i = 0; i < 1000; ++i) ASSERT_LT(rng.uniform_below(7), 7u);
}

TEST(RngTest, StreamIndexSeparatesPairs) {
  EXPECT_NE(stream_index(1, 0), stream_index(0, 1));
  EXPECT_NE(stream_index(5, 3), stream_index(3, 5));
}

TEST(ParallelTest, EveryIndexRunsOnceWhateverTheThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<int> runs(1000, 0);
    parallel_for(runs.size(), threads, [&](std::size_t i) { runs[i] += 1; });
    for (int r : runs) ASSERT_EQ(r, 1);
  }
}

TEST(ParallelTest, ExceptionsReachTheCaller) {
  EXPECT_THROW(parallel_for(100, 2,
                            [](std::size_t i) {
                              if (i == 37) throw std::runtime_error("boom");
                            }),
               std::runtime_error);
}

TEST(LogGridTest, CoversTheRangeEvenlyInLog) {
  const auto grid = log_grid(10, 100000, 4);
  EXPECT_EQ(grid.front(), 10u);
  EXPECT_EQ(grid.back(), 100000u);
  EXPECT_EQ(grid.size(), 17u);  // 4 decades x 4 per decade + 1
  for (std::size_t i = 1; i < grid.size(); ++i) EXPECT_GT(grid[i], grid[i - 1]);
  EXPECT_EQ(log_grid(5, 5, 4), std::vector<std::uint64_t>{5});
}

}  // namespace
