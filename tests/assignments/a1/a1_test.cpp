// Assignment a1, Monte Carlo integration: the public tests (CTest label a1). The procedures
// are in a1_checks.hpp. The written answers (a1.5) are graded by scripts/grade, which reads
// their file as data (scripts/written_answers.py): no test program, no student code.

#include <gtest/gtest.h>

#include <cmath>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A1, Task1DiskEstimateIsUnbiased) {
  const TaskResult r = check_disk_estimator(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task1DiskEstimateIsAMultipleOfFourOverN) {
  const double a = subject().a1_disk(1000, 1, 1);
  EXPECT_DOUBLE_EQ(std::round(a * 1000.0 / 4.0), a * 1000.0 / 4.0)
      << "4 M / N with N = 1000 is a multiple of 0.004";
}

TEST(A1, Task2BallVolumesAreUnbiased) {
  const TaskResult r = check_ball_estimator(subject(), {2, 3, 5});
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task2BallCountStaysWithinN) {
  const std::vector<std::uint64_t> counts = subject().a1_ball_counts({{4, 500}, {1, 500}}, 2, 2);
  EXPECT_LE(counts.at(0), 500u);
  EXPECT_EQ(counts.at(1), 500u) << "every point of [-1,1] is in the 1-ball";
}

TEST(A1, Task3BasicEstimatorIsUnbiasedWithItsStandardError) {
  const TaskResult r = check_basic_estimator(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task3BasicEstimatorIsExactForAConstant) {
  const EstimateAndError e =
      subject().a1_monte_carlo(A1Integrand::constant, 2.5, Segment{-1.0, 3.0}, 100, 3, 3);
  EXPECT_NEAR(e.estimate, 10.0, 1e-12) << "(b - a) * 2.5 with b - a = 4";
  EXPECT_NEAR(e.standard_error, 0.0, 1e-12);
}

TEST(A1, Task4TrapezoidErrorFallsAsHSquared) {
  const TaskResult r = check_trapezoid(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A1, Task4TrapezoidIsExactForALine) {
  for (std::uint64_t n : {2u, 3u, 10u})  // the line 3x + 1
    EXPECT_NEAR(subject().a1_trapezoid(A1Integrand::line, 0.0, Segment{-1.0, 2.0}, n), 7.5, 1e-12)
        << "n = " << n;
}

}  // namespace
}  // namespace mcrt::testing::assignment
