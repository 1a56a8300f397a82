// Russian roulette (common/render/russian_roulette.hpp): its closed forms against direct sums
// and chapter 05's, the survival probability of each policy, exact properties of the path
// loop, the furnace driver's independence of the thread count, and that the statistical
// checks' procedures reject the known-wrong variants of tests/render/russian_roulette_known_bugs.hpp.
// (Its statistical checks against the closed forms are in tests/render/russian_roulette_checks.cpp.)

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "render/russian_roulette_known_bugs.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "stats/check.hpp"
#include "render/russian_roulette_furnace.hpp"

using namespace mcrt;

namespace {

// ---------------------------------------------------------------------------------------------
// Closed forms.

// E[L^2] / Le^2 = sum over i, j of E[I_max(i,j) W_i W_j] / (P_i P_j), summed term by term
// until the terms are negligible: the definition, without the file's algebra.
double second_moment_by_direct_sum(double a, int d, double q) {
  const double b = 4.0 * a * a / 3.0;
  const auto p = [&](int j) { return std::pow(q, std::max(0, j - d)); };
  double sum = 0.0;
  for (int i = 0; i < 400; ++i)
    for (int j = 0; j < 400; ++j) {
      const int lo = std::min(i, j), hi = std::max(i, j);
      sum += p(hi) * std::pow(b, lo) * std::pow(a, hi - lo) / (p(i) * p(j));
    }
  return sum;
}

TEST(RussianRouletteTest, VarianceMatchesTheDirectSumOfItsSeries) {
  for (double a : {0.2, 0.5, 0.7})
    for (int d : {0, 1, 3})
      for (double q : {0.6, 0.8, 0.95}) {
        if (q <= furnace_roulette_variance_threshold(a) + 0.05) continue;  // slow or no sum
        const double mean = 1.0 / (1.0 - a);
        const double expected = 4.0 * (second_moment_by_direct_sum(a, d, q) - mean * mean);
        // 1e-9 relative: the truncated tails are below (b/q)^400, far below round-off.
        EXPECT_NEAR(furnace_roulette_variance(a, 2.0, d, q), expected, 1e-9 * expected)
            << "a " << a << " d " << d << " q " << q;
      }
}

TEST(RussianRouletteTest, WithoutRouletteTheVarianceIsTheDeepDepthCuts) {
  // q = 1 is chapter 05's tracer with no cut: its variance at k -> infinity (k = 300 here,
  // where b^k and a^k are below 1e-30).
  for (double a : {0.3, 0.5, 0.8})
    EXPECT_NEAR(furnace_roulette_variance(a, 1.5, 3, 1.0), furnace_radiance_variance(a, 1.5, 300),
                1e-9)
        << a;
}

TEST(RussianRouletteTest, VarianceIsInfiniteAtAndBelowTheThreshold) {
  const double b = furnace_roulette_variance_threshold(0.6);  // 0.48
  EXPECT_DOUBLE_EQ(b, 0.48);
  EXPECT_TRUE(std::isinf(furnace_roulette_variance(0.6, 1.0, 3, b)));
  EXPECT_TRUE(std::isinf(furnace_roulette_variance(0.6, 1.0, 3, 0.3)));
  EXPECT_TRUE(std::isfinite(furnace_roulette_variance(0.6, 1.0, 3, b + 1e-3)));
  // Stopping more often costs variance: it falls as q rises.
  EXPECT_GT(furnace_roulette_variance(0.6, 1.0, 3, 0.5),
            furnace_roulette_variance(0.6, 1.0, 3, 0.9));
}

TEST(RussianRouletteTest, DepthCutBiasIsWhatTheCutLoses) {
  for (double a : {0.1, 0.5, 0.9})
    for (int k : {0, 1, 5, 20})
      EXPECT_NEAR(furnace_depth_cut_bias(a, 2.0, k),
                  furnace_radiance(a, 2.0, k) - furnace_radiance_untruncated(a, 2.0), 1e-12);
}

TEST(RussianRouletteTest, PathLengthLawSumsToOneWithMeanDPlusOneOverOneMinusQ) {
  for (int d : {0, 3})
    for (double q : {0.2, 0.7, 0.9}) {
      double total = 0.0, mean = 0.0;
      for (int r = 0; r < 2000; ++r) {
        const double p = furnace_roulette_length_probability(d, q, r);
        total += p;
        mean += r * p;
      }
      EXPECT_NEAR(total, 1.0, 1e-12);
      EXPECT_NEAR(mean, furnace_roulette_mean_rays(d, q), 1e-9);
      EXPECT_EQ(furnace_roulette_length_probability(d, q, d), 0.0);  // never shorter than d + 1
    }
}

// ---------------------------------------------------------------------------------------------
// The estimator.

TEST(RussianRouletteTest, SurvivalProbabilityOfEachPolicy) {
  const Roulette fixed{3, RoulettePolicy::fixed, 0.6, 0.05};
  EXPECT_EQ(survival_probability(fixed, Color(5.0)), 0.6);
  const Roulette throughput{3, RoulettePolicy::throughput, 0.6, 0.05};
  EXPECT_EQ(survival_probability(throughput, Color(0.2, 0.5, 0.3)), 0.5);  // the largest part
  EXPECT_EQ(survival_probability(throughput, Color(1.7, 0.1, 0.1)), 1.0);  // clamped to 1
  EXPECT_EQ(survival_probability(throughput, Color(0.001)), 0.05);         // the floor
}

TEST(RussianRouletteTest, BeforeTheMinimumDepthItIsTheDepthCutsPath) {
  // With the same random numbers, roulette after d draws nothing more than the depth cut at d
  // until vertex d, so its estimate is the cut's plus the (non-negative) light of later
  // vertices, and it traces at least d + 1 rays in the closed furnace.
  const Scene furnace = make_furnace(0.6, 1.0);
  for (int d : {0, 2, 5})
    for (std::uint64_t i = 0; i < 200; ++i) {
      const Ray ray{Vec3(0.0), Vec3(0.0, 0.0, 1.0)};
      Rng cut_rng(7, i), roulette_rng(7, i);
      RayCount cut_count, roulette_count;
      const Color cut = estimate_path_radiance(furnace, ray, d, cut_rng, cut_count);
      const Color roulette =
          estimate_path_radiance_roulette(furnace, ray, {d, RoulettePolicy::fixed, 0.5, 0.05},
                                          roulette_rng, roulette_count);
      EXPECT_GE(roulette.r, cut.r - 1e-12);
      EXPECT_GE(roulette_count.rays, static_cast<std::uint64_t>(d) + 1);
      EXPECT_EQ(cut_count.rays, static_cast<std::uint64_t>(d) + 1);
    }
}

TEST(RussianRouletteTest, BlackFurnaceGivesExactlyItsEmission) {
  // a = 0: the weight is 0 after the first bounce, so L = Le exactly, one ray per path.
  const Scene furnace = make_furnace(0.0, 2.5);
  const auto paths = trace_furnace_paths(100, 3, 0, 1, [&](const Ray& ray, Rng& rng, RayCount& c) {
    return estimate_path_radiance_roulette(furnace, ray, {0, RoulettePolicy::throughput, 0.5, 0.05},
                                           rng, c);
  });
  for (const FurnacePath& path : paths) {
    EXPECT_EQ(path.radiance, 2.5);
    EXPECT_EQ(path.rays, 1u);
  }
}

TEST(RussianRouletteTest, FurnacePathsAndImagesDoNotDependOnTheThreadCount) {
  const Scene furnace = make_furnace(0.7, 1.0);
  const Roulette roulette{2, RoulettePolicy::throughput, 0.5, 0.05};
  const auto estimate = [&](const Ray& ray, Rng& rng, RayCount& c) {
    return estimate_path_radiance_roulette(furnace, ray, roulette, rng, c);
  };
  const auto one = trace_furnace_paths(10000, 5, 9, 1, estimate);
  const auto two = trace_furnace_paths(10000, 5, 9, 2, estimate);
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one[i].radiance, two[i].radiance) << i;
    ASSERT_EQ(one[i].rays, two[i].rays) << i;
  }

  const Scene cornell = make_cornell_box();
  const Camera camera(cornell.camera, 16, 12);
  const auto render_with = [&](int threads) {
    return render(camera, {4, 0, 3, threads, nullptr}, [&](const Ray& ray, Rng& rng, RayCount& c) {
      return estimate_path_radiance_roulette(cornell, ray, roulette, rng, c);
    });
  };
  const RenderResult a = render_with(1), b = render_with(2);
  EXPECT_EQ(a.image.pixels, b.image.pixels);
  EXPECT_EQ(a.rays, b.rays);
  EXPECT_EQ(a.non_finite_samples, 0u);
}

// ---------------------------------------------------------------------------------------------
// Known-wrong roulette: the same procedures, sample sizes, seed and stream blocks as the checks
// roulette_furnace_mean_fixed_a05_d3_q07 (block 601), roulette_furnace_mean_throughput_a07_d3
// (603) and roulette_path_length_geometric_d3_q07 (621), alpha = 1e-4.

using mcrt::testing::RouletteFurnaceSetup;
constexpr int k_paths = 40000;
constexpr double k_alpha = 1e-4;

template <class Estimator>
double mean_p(const RouletteFurnaceSetup& setup, std::uint64_t block, Estimator estimate) {
  return mcrt::testing::roulette_mean_p_value(
      setup, mcrt::testing::roulette_furnace_paths(setup, k_paths, mcrt::testing::k_suite_seed,
                                                   block, estimate));
}

const RouletteFurnaceSetup k_fixed{0.5, 1.0, {3, RoulettePolicy::fixed, 0.7, 0.05}};
const RouletteFurnaceSetup k_throughput{0.7, 1.0, {3, RoulettePolicy::throughput, 0.7, 0.05}};

TEST(RussianRouletteKnownBugsTest, FurnaceMeanTestRejectsBiasedRoulette) {
  using namespace mcrt::testing;
  // The right estimator passes at this seed (its false-failure rate is 1e-4)...
  EXPECT_GE(mean_p(k_fixed, 601, chapter_roulette), k_alpha);
  EXPECT_GE(mean_p(k_throughput, 603, chapter_roulette), k_alpha);
  // ... and every biased one is rejected.
  EXPECT_LT(mean_p(k_fixed, 601, roulette_without_division), k_alpha);
  EXPECT_LT(mean_p(k_fixed, 601, roulette_before_emission), k_alpha);
  EXPECT_LT(mean_p(k_throughput, 603, roulette_without_division), k_alpha);
  EXPECT_LT(mean_p(k_throughput, 603, roulette_q_not_clamped), k_alpha);
}

TEST(RussianRouletteKnownBugsTest, PathLengthTestRejectsRouletteFromDepthZero) {
  using namespace mcrt::testing;
  const auto lengths_p = [](auto estimate) {
    const auto paths = roulette_furnace_paths(k_fixed, k_paths, k_suite_seed, 621, estimate);
    return path_length_test(3, 0.7, paths).p_value;
  };
  EXPECT_GE(lengths_p(chapter_roulette), k_alpha);
  EXPECT_LT(lengths_p(roulette_from_depth_zero), k_alpha);
  // Its mean is right (roulette from depth 0 is unbiased): a t-test of it passes, so only the
  // path lengths (or the variance) can tell it from the right estimator.
  RunningStats radiance;
  for (const FurnacePath& path :
       roulette_furnace_paths(k_fixed, k_paths, k_suite_seed, 601, roulette_from_depth_zero))
    radiance.add(path.radiance);
  EXPECT_GE(t_test_p_value(radiance.mean(), radiance.variance(), radiance.count(), 2.0), k_alpha);
}

}  // namespace
