// permutation_element (sampling/permutation.hpp): a bijection of {0..n-1} for every n and key,
// and different keys give different permutations. (Each element's place is uniform over keys:
// point_sets_test.cpp checks it through the points that use it.)

#include <cstdint>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "sampling/permutation.hpp"

using namespace mcrt;

namespace {

TEST(PermutationTest, IsABijectionForEverySizeAndKey) {
  for (std::uint32_t n = 1; n <= 300; ++n)
    for (std::uint64_t key : {0ull, 1ull, 0xdeadbeefull}) {
      std::set<std::uint32_t> seen;
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t p = permutation_element(i, n, key);
        ASSERT_LT(p, n);
        seen.insert(p);
      }
      ASSERT_EQ(seen.size(), n) << "n = " << n;
    }
  std::vector<bool> hit(100003, false);  // a prime, far from a power of two
  for (std::uint32_t i = 0; i < hit.size(); ++i) hit[permutation_element(i, 100003, 7)] = true;
  for (const bool h : hit) ASSERT_TRUE(h);
}

TEST(PermutationTest, DifferentKeysGiveDifferentPermutations) {
  int same = 0;
  for (std::uint32_t i = 0; i < 1000; ++i)
    same += permutation_element(i, 1000, 1) == permutation_element(i, 1000, 2);
  // Two independent random permutations agree at about one place (a Poisson(1) count):
  // 10 or more has probability about 1e-7.
  EXPECT_LT(same, 10);
}

}  // namespace
