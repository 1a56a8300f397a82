// Splitting (common/render/splitting.hpp) against its closed forms in the furnace (albedo a,
// emission Le), fixed-q roulette after d, the first s vertices split n ways:
//  - the mean radiance is Le / (1 - a), the geometric series, whatever n: z-tests with the
//    standard error from the closed-form variance;
//  - the rays a path traces have the mean R_s (R_0 = d - s + 1/(1 - q), R_j = 1 + n R_{j-1})
//    and the variance n^s q / (1 - q)^2: z-tests;
//  - the variance is Var_s (Var_j = (b (Var_{j-1} + m^2) - a^2 m^2) / n): the variance test.
// Every check is designed for a false-failure rate alpha = 1e-4.
//
// The moments each test needs are those of chapter 06's roulette checks (splitting averages
// independent roulette tails, which keeps every moment they have): past vertex d the p-th
// moment is a series in (2a)^p / ((p + 1) q^(p-1)), finite when that is below 1.

#include <cstdint>
#include <vector>

#include "render/splitting.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"
#include "render/splitting_furnace.hpp"

namespace {

using namespace mcrt;
using mcrt::testing::SplittingFurnaceSetup;

constexpr int k_paths = 20000;

// a = 0.5, d = 3, q = 0.7, the first hit split 4 ways: up to the fourth moment finite
// ((2a)^4 / (5 q^3) = 0.58).
const SplittingFurnaceSetup k_first_hit{0.5, 1.0, {3, RoulettePolicy::fixed, 0.7, 0.05}, {1, 4}};
// a = 0.6, Le = 2, d = 2, q = 0.8, two vertices split 3 ways (9 tails): fourth moment 0.81.
const SplittingFurnaceSetup k_two_vertices{0.6, 2.0, {2, RoulettePolicy::fixed, 0.8, 0.05}, {2, 3}};

// Stream blocks: 700 + the check, apart from the other checks' blocks.
std::vector<FurnacePath> paths(const SplittingFurnaceSetup& setup, std::uint64_t seed,
                               std::uint64_t block) {
  return mcrt::testing::splitting_furnace_paths(setup, k_paths, seed, 700 + block,
                                                mcrt::testing::chapter_splitting);
}

MCRT_STATISTICAL_CHECK(splitting_furnace_mean_a05_d3_q07_s1_n4, 1e-4) {
  return mcrt::testing::splitting_mean_p_value(k_first_hit, paths(k_first_hit, seed, 1));
}
MCRT_STATISTICAL_CHECK(splitting_furnace_mean_a06_d2_q08_s2_n3, 1e-4) {
  return mcrt::testing::splitting_mean_p_value(k_two_vertices, paths(k_two_vertices, seed, 2));
}
MCRT_STATISTICAL_CHECK(splitting_rays_a05_d3_q07_s1_n4, 1e-4) {
  return mcrt::testing::splitting_rays_p_value(k_first_hit, paths(k_first_hit, seed, 11));
}
MCRT_STATISTICAL_CHECK(splitting_rays_a06_d2_q08_s2_n3, 1e-4) {
  return mcrt::testing::splitting_rays_p_value(k_two_vertices, paths(k_two_vertices, seed, 12));
}

// The variance Var_2 at a = 0.5, d = 2, q = 0.9, two vertices split 3 ways: the eighth moment's
// ratio (2a)^8 / (9 q^7) = 0.23, as chapter 06's roulette variance check.
MCRT_STATISTICAL_CHECK(splitting_furnace_variance_a05_d2_q09_s2_n3, 1e-4) {
  const SplittingFurnaceSetup setup{0.5, 1.0, {2, RoulettePolicy::fixed, 0.9, 0.05}, {2, 3}};
  const double expected = furnace_splitting_variance(0.5, 1.0, 2, 0.9, setup.splitting);
  return mcrt::testing::variance_z_test_p_value(mcrt::testing::splitting_radiance_values(
                                                    paths(setup, seed, 21)),
                                                expected);
}

}  // namespace
