// Runs every registered statistical check once, at the suite's fixed seed, as one GoogleTest
// test each: it passes when the check's p-value is at least its alpha.

#include <gtest/gtest.h>

#include "stats/check.hpp"

namespace {

class CheckTest : public ::testing::Test {
 public:
  explicit CheckTest(const mcrt::testing::StatisticalCheck& check) : check_(check) {}
  void TestBody() override {
    const double p = check_.p_value(mcrt::testing::k_suite_seed);
    EXPECT_GE(p, check_.alpha) << check_.name << " rejected at seed " << mcrt::testing::k_suite_seed
                               << ": p = " << p << " < alpha = " << check_.alpha;
  }

 private:
  const mcrt::testing::StatisticalCheck& check_;
};

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (const auto& check : mcrt::testing::statistical_checks())
    ::testing::RegisterTest("StatisticalCheck", check.name.c_str(), nullptr, nullptr, __FILE__,
                            __LINE__,
                            [&check]() -> ::testing::Test* { return new CheckTest(check); });
  return RUN_ALL_TESTS();
}
