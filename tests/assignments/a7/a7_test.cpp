// Assignment a7, stratified sampling: the public tests (CTest label a7). Each point set is
// graded by its stratification, checked exactly at three keys, and by a point's uniformity over
// randomisations (a chi-square); jittered points also by how fast their estimate's variance
// falls; the radical inverse by the recurrence that defines it (a7_checks.hpp).

#include <gtest/gtest.h>

#include "assignments/a7/a7_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A7, Task1JitteredHasOnePointPerStratum) {
  const TaskResult r = check_jittered_strata(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task1JitteredPointIsUniform) {
  const TaskResult r = check_jittered_uniform(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task1JitteredVarianceFallsAsOneOverNSquared) {
  const TaskResult r = check_jittered_rate(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task2LatinHypercubeHasOnePointPerSlab) {
  const TaskResult r = check_latin_slabs(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task2LatinHypercubeDimensionsAreIndependent) {
  const TaskResult r = check_latin_uniform(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task3RadicalInverseMirrorsTheDigits) {
  const TaskResult r = check_radical_inverse(subject(), {2, 3, 5, 7});
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task4ScrambledHaltonHasOnePointPerBox) {
  const TaskResult r = check_halton_boxes(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A7, Task4ScrambledHaltonPointIsUniform) {
  const TaskResult r = check_halton_uniform(subject());
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
