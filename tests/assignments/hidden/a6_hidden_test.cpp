// Hidden tests of a6 (their parameters travel as requests: the subject holds no hidden test):
// the lobe at other exponents than the public tests' m = 10.

#include <gtest/gtest.h>

#include "assignments/a6/a6_checks.hpp"
#include "assignments/subject/subject.hpp"

namespace mcrt::testing::assignment {
namespace {

TEST(A6Hidden, LobeAtMThreeFollowsItsPdf) {
  const TaskResult r = check_lobe_sampler(subject(), 3.0);
  EXPECT_TRUE(r.passed) << r.message;
}

TEST(A6Hidden, LobePdfAtMOneIntegratesToOne) {
  const TaskResult r = check_lobe_pdf_integral(subject(), 1.0);
  EXPECT_TRUE(r.passed) << r.message;
}

}  // namespace
}  // namespace mcrt::testing::assignment
