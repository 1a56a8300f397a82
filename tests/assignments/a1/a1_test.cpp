// Assignment a1, Monte Carlo integration: the public tests (CTest label a1). The procedures
// are in a1_checks.hpp; the written answers' values are checked by the hidden tests.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "assignments/a1/a1_checks.hpp"
#include "integration/quadrature.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A1, Task1DiskEstimateIsUnbiased) {
  const TaskResult r = check_disk_estimator([](std::uint64_t n, Rng& rng) { return estimate_disk_area(n, rng); });
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task1DiskEstimateIsAMultipleOfFourOverN) {
  Rng rng(1, 1);
  const double a = estimate_disk_area(1000, rng);
  EXPECT_DOUBLE_EQ(std::round(a * 1000.0 / 4.0), a * 1000.0 / 4.0) << "4 M / N with N = 1000 is a multiple of 0.004";
}

TEST(A1, Task2BallVolumesAreUnbiased) {
  const TaskResult r = check_ball_estimator(
      [](int k, std::uint64_t n, Rng& rng) { return estimate_ball_volume(k, n, rng); }, {2, 3, 5});
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task2BallCountStaysWithinN) {
  Rng rng(2, 2);
  EXPECT_LE(count_in_ball(4, 500, rng), 500u);
  EXPECT_EQ(count_in_ball(1, 500, rng), 500u) << "every point of [-1,1] is in the 1-ball";
}

TEST(A1, Task3BasicEstimatorIsUnbiasedWithItsStandardError) {
  const TaskResult r = check_basic_estimator([](const auto& f, const Segment& s, std::uint64_t n, Rng& rng) {
    return monte_carlo(f, s, n, rng);
  });
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task3BasicEstimatorIsExactForAConstant) {
  Rng rng(3, 3);
  const MonteCarloEstimate e = monte_carlo([](double) { return 2.5; }, Segment{-1.0, 3.0}, 100, rng);
  EXPECT_NEAR(e.estimate, 10.0, 1e-12) << "(b - a) * 2.5 with b - a = 4";
  EXPECT_NEAR(e.standard_error, 0.0, 1e-12);
}

TEST(A1, Task4TrapezoidErrorFallsAsHSquared) {
  const TaskResult r = check_trapezoid([](std::uint64_t n) { return trapezoid(Gaussian1D{}, Gaussian1D{}.domain, n); });
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task4TrapezoidIsExactForALine) {
  const auto line = [](double x) { return 3.0 * x + 1.0; };
  for (std::uint64_t n : {2u, 3u, 10u})
    EXPECT_NEAR(trapezoid(line, Segment{-1.0, 2.0}, n), 7.5, 1e-12) << "n = " << n;
}

// The answers file: every number present and finite (their values are graded by hidden tests).
TEST(A1, Task5AnswersFileIsComplete) {
  std::ifstream in(MCRT_A1_ANSWERS);
  ASSERT_TRUE(in) << "cannot read " << MCRT_A1_ANSWERS;
  const nlohmann::json answers = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(answers.is_discarded()) << MCRT_A1_ANSWERS << " is not valid JSON";
  for (const char* key : {"E_Y", "V_Y", "E_M", "V_M", "V_estimate"}) {
    ASSERT_TRUE(answers.contains(key) && answers[key].is_number())
        << "not implemented: a1.5 answer " << key << " in " << MCRT_A1_ANSWERS
        << " (a number, for p = pi/4 and N = 1000)";
    EXPECT_TRUE(std::isfinite(answers[key].get<double>())) << key;
  }
}

}  // namespace
}  // namespace mcrt::testing::assignment
