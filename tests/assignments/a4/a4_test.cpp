// Assignment a4, the path tracer: the public tests (CTest label a4), graded on the furnace's
// closed forms and on region-by-region agreement with a reference render (a4_checks.hpp). The
// tracer is reached through subject() only (in-process, or the subject program of a checker).

#include <gtest/gtest.h>

#include "assignments/a4/a4_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A4, Task1FurnaceMeanAndVarianceMatchTheClosedForms) {
  const TaskResult r = check_path_furnace(furnace_of_subject(subject()));
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A4, Task1RegionsAgreeWithTheReference) {
  const RegionResult r = check_reference_regions(sky_of_subject(subject()));
  report_error_map(r.map, "a4_regions");  // the checker's: from the samples, in its report folder
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A4, Task1TracesAtMostKPlusOneRays) {
  const PathSample p = subject().path_single(0.5, 1.0, {0.0, 0.0, 1.0}, 5, 3, 3);
  EXPECT_EQ(p.rays, 6u) << "k = 5 bounces: k + 1 closest-hit queries in the furnace";
}

TEST(A4, Task1DepthZeroIsTheEmission) {
  EXPECT_DOUBLE_EQ(subject().path_single(0.5, 1.5, {0.0, 1.0, 0.0}, 0, 3, 4).radiance, 1.5)
      << "with max_depth 0 the path is the first hit's emission";
}

TEST(A4, Task2PixelMeanAndStandardErrorAreExact) {
  const TaskResult r = check_pixel_exact(pixel_exact_of_subject(subject()));
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A4, Task2JitterCoversThePixelUniformly) {
  const TaskResult r = check_pixel_jitter(pixel_rays_of_subject(subject()));
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A4, Task2StandardErrorIsCalibrated) {
  const TaskResult r = check_pixel_calibration(pixel_furnace_of_subject(subject()));
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
