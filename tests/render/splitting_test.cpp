// Splitting (common/render/splitting.hpp): its closed forms against roulette's, exact
// properties of the split path (one branch is roulette, the fewest rays a path can trace, the
// same paths whatever the thread count), and that the statistical checks' procedures reject
// the known-wrong variants of tests/render/splitting_known_bugs.hpp.
// (Its statistical checks against the closed forms are in tests/render/splitting_checks.cpp.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "render/splitting.hpp"
#include "render/splitting_furnace.hpp"
#include "render/splitting_known_bugs.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"

using namespace mcrt;
using mcrt::testing::SplittingFurnaceSetup;

namespace {

// ---------------------------------------------------------------------------------------------
// Closed forms.

TEST(SplittingTest, OneBranchOrNoSplittingIsRoulettesClosedForm) {
  for (double a : {0.3, 0.5, 0.7})
    for (int d : {1, 3})
      for (double q : {0.7, 0.9}) {
        const double variance = furnace_roulette_variance(a, 1.5, d, q);
        for (const Splitting s : {Splitting{0, 4}, Splitting{1, 1}, Splitting{d, 1}}) {
          // 1e-12 relative: the same sums in another order.
          EXPECT_NEAR(furnace_splitting_variance(a, 1.5, d, q, s), variance, 1e-12 * variance)
              << a << " " << d << " " << q << " s " << s.depth << " n " << s.n;
          EXPECT_NEAR(furnace_splitting_mean_rays(d, q, s), furnace_roulette_mean_rays(d, q),
                      1e-12);
        }
      }
}

TEST(SplittingTest, SplittingTheFirstHitDividesTheVarianceByNAndCopiesTheTail) {
  // L = Le + (1/n) sum_k w_k T_k: the n terms are independent, each has roulette's Var[w T].
  for (int n : {2, 3, 8}) {
    const Splitting s{1, n};
    EXPECT_NEAR(furnace_splitting_variance(0.5, 1.0, 3, 0.7, s),
                furnace_roulette_variance(0.5, 1.0, 3, 0.7) / n, 1e-12);
    EXPECT_DOUBLE_EQ(furnace_splitting_mean_rays(3, 0.7, s), 1.0 + n * (2.0 + 1.0 / 0.3));
  }
}

// ---------------------------------------------------------------------------------------------
// The split path.

TEST(SplittingTest, OneBranchIsRoulettePathForPath) {
  // n = 1 draws the same random numbers in the same order as chapter 06's roulette loop: the
  // same rays exactly, the same radiance but for the order of the sums (1e-12 relative).
  const Roulette roulette{2, RoulettePolicy::throughput, 0.7, 0.05};
  // smallpt has a mirror and glass: the delta branch too.
  for (const Scene& scene :
       {make_furnace(0.6, 1.0), make_scene("cornell-spheres"), make_scene("smallpt")}) {
    for (std::uint64_t i = 0; i < 2000; ++i) {
      Rng rng_split(9, i), rng_roulette(9, i);
      const Ray ray{scene.name == "furnace" ? Vec3(0.0) : scene.camera.eye,
                    sample_uniform_sphere(Rng(8, i).uniform2())};
      RayCount split_rays, roulette_rays;
      const Color split =
          estimate_path_radiance_splitting(scene, ray, roulette, {3, 1}, rng_split, split_rays);
      const Color plain =
          estimate_path_radiance_roulette(scene, ray, roulette, rng_roulette, roulette_rays);
      ASSERT_EQ(split_rays.rays, roulette_rays.rays) << scene.name << " path " << i;
      ASSERT_NEAR(average(split), average(plain), 1e-12 * (1.0 + average(plain)))
          << scene.name << " path " << i;
    }
  }
}

TEST(SplittingTest, EveryBranchTracesItsFirstBouncesInFull) {
  // The first hit split 4 ways, roulette after d = 3: the camera ray, then 4 branches of at
  // least d rays each (vertices 1..d); all 4 stop at their first roulette with (1 - q)^4.
  const SplittingFurnaceSetup setup{0.5, 1.0, {3, RoulettePolicy::fixed, 0.7, 0.05}, {1, 4}};
  const auto paths =
      mcrt::testing::splitting_furnace_paths(setup, 20000, 3, 1, mcrt::testing::chapter_splitting);
  std::uint64_t fewest = ~std::uint64_t{0}, at_fewest = 0;
  for (const FurnacePath& path : paths) fewest = std::min(fewest, path.rays);
  for (const FurnacePath& path : paths) at_fewest += path.rays == fewest;
  EXPECT_EQ(fewest, 13u);
  // (1 - q)^4 = 0.0081 of 20000 paths: 162 expected, sd 12.7; 5 sd either way.
  EXPECT_NEAR(static_cast<double>(at_fewest), 162.0, 64.0);
}

TEST(SplittingTest, SamePathsWhateverTheThreadCount) {
  const SplittingFurnaceSetup setup{0.5, 1.0, {3, RoulettePolicy::throughput, 0.7, 0.05}, {2, 3}};
  const auto trace = [&](int threads) {
    return mcrt::testing::splitting_furnace_paths(setup, 9000, 4, 2,
                                                  mcrt::testing::chapter_splitting, threads);
  };
  const std::vector<FurnacePath> one = trace(1), three = trace(3);
  ASSERT_EQ(one.size(), three.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].radiance, three[i].radiance) << i;
    ASSERT_EQ(one[i].rays, three[i].rays) << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Known-wrong splitting: the same procedures, sample sizes, seed and stream blocks as the
// checks splitting_furnace_mean_a05_d3_q07_s1_n4 (block 701) and
// splitting_furnace_variance_a05_d2_q09_s2_n3 (721), alpha = 1e-4.

constexpr int k_paths = 20000;
constexpr double k_alpha = 1e-4;
const SplittingFurnaceSetup k_first_hit{0.5, 1.0, {3, RoulettePolicy::fixed, 0.7, 0.05}, {1, 4}};
const SplittingFurnaceSetup k_variance{0.5, 1.0, {2, RoulettePolicy::fixed, 0.9, 0.05}, {2, 3}};

template <class Estimator>
std::vector<FurnacePath> suite_paths(const SplittingFurnaceSetup& setup, std::uint64_t block,
                                     Estimator estimate) {
  return mcrt::testing::splitting_furnace_paths(setup, k_paths, mcrt::testing::k_suite_seed, block,
                                                estimate);
}

TEST(SplittingKnownBugsTest, FurnaceMeanTestRejectsBranchesWithTheWholeWeight) {
  using namespace mcrt::testing;
  EXPECT_GE(splitting_mean_p_value(k_first_hit, suite_paths(k_first_hit, 701, chapter_splitting)),
            k_alpha);
  EXPECT_LT(splitting_mean_p_value(k_first_hit,
                                   suite_paths(k_first_hit, 701, splitting_without_division)),
            k_alpha);
}

TEST(SplittingKnownBugsTest, VarianceTestRejectsBranchesSharingOneDirection) {
  using namespace mcrt::testing;
  const double expected = furnace_splitting_variance(0.5, 1.0, 2, 0.9, k_variance.splitting);
  const auto variance_p = [&](const std::vector<FurnacePath>& paths) {
    return variance_z_test_p_value(splitting_radiance_values(paths), expected);
  };
  EXPECT_GE(variance_p(suite_paths(k_variance, 721, chapter_splitting)), k_alpha);
  const std::vector<FurnacePath> shared = suite_paths(k_variance, 721, splitting_one_direction);
  EXPECT_LT(variance_p(shared), k_alpha);
  // Its mean is right (each branch is still an unbiased estimate): only the variance sees it.
  EXPECT_GE(splitting_mean_p_value(k_variance, shared), k_alpha);
}

}  // namespace
