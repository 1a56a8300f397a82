// Russian roulette (common/render/russian_roulette.hpp) against its closed forms in the
// furnace (albedo a, emission Le), with no depth cut:
//  - the mean radiance is Le / (1 - a): z-tests for fixed q (the standard error from the
//    closed-form variance), a t-test for the throughput policy;
//  - the variance of fixed q is Le^2 ((1 + a)/(1 - a) S(q) - 1/(1 - a)^2): the suite's one
//    variance test (stats/hypothesis.hpp);
//  - the rays a fixed-q path traces follow the geometric law d + 1 + M, P(M = m) = q^m (1 - q):
//    chi-square.
// Every check is designed for a false-failure rate alpha = 1e-4.
//
// The setups keep the moments each test needs finite. Past vertex d the estimate's p-th moment
// is a series in E[(2 a c)^p] / q^(p-1) = (2a)^p / ((p + 1) q^(p-1)), finite when that is
// below 1: the mean tests need the variance (p = 2) and, for a normal mean at n = 4e4, the
// third moment; the variance test needs the eighth (its kurtosis is estimated from the data).

#include <cstdint>
#include <vector>

#include "render/russian_roulette.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"
#include "render/russian_roulette_furnace.hpp"

namespace {

using namespace mcrt;
using mcrt::testing::RouletteFurnaceSetup;

constexpr int k_paths = 40000;

// Stream blocks: 600 + the check, apart from the other checks' blocks.
double mean_check(std::uint64_t seed, std::uint64_t block, const RouletteFurnaceSetup& setup) {
  const std::vector<FurnacePath> paths =
      mcrt::testing::roulette_furnace_paths(setup, k_paths, seed, 600 + block,
                                            mcrt::testing::chapter_roulette);
  return mcrt::testing::roulette_mean_p_value(setup, paths);
}

// a = 0.5, d = 3, q = 0.7: (2a)^3 / (4 q^2) = 0.51 and (2a)^4 / (5 q^3) = 0.58: up to the
// fourth moment finite.
MCRT_STATISTICAL_CHECK(roulette_furnace_mean_fixed_a05_d3_q07, 1e-4) {
  return mean_check(seed, 1, {0.5, 1.0, {3, RoulettePolicy::fixed, 0.7, 0.05}});
}
// a = 0.6, d = 0 (roulette from the first hit), q = 0.8: third moment 0.68, fourth 0.81.
MCRT_STATISTICAL_CHECK(roulette_furnace_mean_fixed_a06_d0_q08, 1e-4) {
  return mean_check(seed, 2, {0.6, 2.0, {0, RoulettePolicy::fixed, 0.8, 0.05}});
}
// The throughput policy at a = 0.7, where one bounce can raise the weight (2 a c up to 1.4)
// and q = 1 until it falls below 1: the largest weight has a power tail of index ~5.6 (the
// root of (2a)^k / (k + 1) = 1), so four moments are finite.
MCRT_STATISTICAL_CHECK(roulette_furnace_mean_throughput_a07_d3, 1e-4) {
  return mean_check(seed, 3, {0.7, 1.0, {3, RoulettePolicy::throughput, 0.7, 0.05}});
}
// The throughput policy at a = 0.3: weights stay below 1, every moment is finite.
MCRT_STATISTICAL_CHECK(roulette_furnace_mean_throughput_a03_d1, 1e-4) {
  return mean_check(seed, 4, {0.3, 1.5, {1, RoulettePolicy::throughput, 0.7, 0.05}});
}

// The variance of fixed q. a = 0.5, q = 0.9: the eighth moment's ratio (2a)^8 / (9 q^7) = 0.23.
MCRT_STATISTICAL_CHECK(roulette_furnace_variance_a05_d2_q09, 1e-4) {
  const RouletteFurnaceSetup setup{0.5, 1.0, {2, RoulettePolicy::fixed, 0.9, 0.05}};
  const std::vector<FurnacePath> paths =
      mcrt::testing::roulette_furnace_paths(setup, k_paths, seed, 611,
                                            mcrt::testing::chapter_roulette);
  const double expected = furnace_roulette_variance(0.5, 1.0, 2, 0.9);
  return mcrt::testing::variance_z_test_p_value(mcrt::testing::radiance_values(paths), expected);
}

// Path lengths: the geometric law after d + 1 rays. The radiance plays no part, only the rays.
double path_length_check(std::uint64_t seed, std::uint64_t block, double albedo, int min_depth,
                         double q) {
  const RouletteFurnaceSetup setup{albedo, 1.0, {min_depth, RoulettePolicy::fixed, q, 0.05}};
  const std::vector<FurnacePath> paths =
      mcrt::testing::roulette_furnace_paths(setup, k_paths, seed, 600 + block,
                                            mcrt::testing::chapter_roulette);
  return mcrt::testing::path_length_test(min_depth, q, paths).p_value;
}

MCRT_STATISTICAL_CHECK(roulette_path_length_geometric_d3_q07, 1e-4) {
  return path_length_check(seed, 21, 0.5, 3, 0.7);
}
MCRT_STATISTICAL_CHECK(roulette_path_length_geometric_d0_q04, 1e-4) {
  return path_length_check(seed, 22, 0.8, 0, 0.4);
}

}  // namespace
