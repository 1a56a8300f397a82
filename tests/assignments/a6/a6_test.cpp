// Assignment a6, glossy surfaces and multiple importance sampling: the public tests (CTest
// label a6). The Phong lobe's sampler and pdf are graded by the chi-square test and by the pdf
// integrating to 1, the heuristics exactly, the MIS estimator region by region on Veach's
// plates and by its variance at equal rays (a6_checks.hpp); the dielectric's sampling by the
// glass ball's invisibility in a furnace and by the frequency of its reflections
// (a6_dielectric_checks.hpp).

#include <gtest/gtest.h>

#include "assignments/a6/a6_checks.hpp"
#include "assignments/a6/a6_dielectric_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A6, Task1LobeFollowsItsPdf) {
  const TaskResult r = check_lobe_sampler(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task1LobePdfIntegratesToOne) {
  const TaskResult r = check_lobe_pdf_integral(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task1LobePdfIsRoundTheMirrorDirection) {
  const TaskResult r = check_lobe_pdf_round_mirror(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task1SharpLobeKeepsItsDigits) {
  const TaskResult r = check_sharp_lobe_digits(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task2BalanceHeuristicIsExact) {
  const TaskResult r = check_heuristic(subject(), A6Heuristic::balance);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task2PowerHeuristicIsExact) {
  const TaskResult r = check_heuristic(subject(), A6Heuristic::power);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task3BalanceRegionsAgreeWithTheReference) {
  const RegionResult r = check_mis_regions(subject(), A6Strategy::mis_balance);
  report_error_map(r.map,
                   "a6_balance_regions");  // the checker's: from the samples, in its report folder
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task3PowerRegionsAgreeWithTheReference) {
  const RegionResult r = check_mis_regions(subject(), A6Strategy::mis_power);
  report_error_map(r.map,
                   "a6_power_regions");  // the checker's: from the samples, in its report folder
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task3MisBeatsEachStrategyAtEqualRays) {
  const TaskResult r = check_mis_efficiency(subject(), A6Strategy::mis_balance);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task4GlassBallIsInvisibleInTheFurnace) {
  const TaskResult r = check_dielectric_furnace(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6, Task4ReflectsInTheFresnelFraction) {
  const TaskResult r = check_dielectric_branches(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
