// Refusing work up front (common/app/ray_limit.hpp, common/app/work_limit.hpp): the limit is
// inclusive and exact, and the refusal is one line naming the flags, the predicted amount, the
// limit and the remedy. The chapters' tests check that their runs are refused; these check where
// the line between refused and accepted falls, which a chapter's far-over-the-limit runs cannot.

#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "app/cli.hpp"
#include "app/ray_limit.hpp"
#include "app/work_limit.hpp"
#include "support/exception_message.hpp"

namespace {

using mcrt::UsageError;

/// The message of the UsageError `refuse` throws; empty if it throws nothing.
template <class Refuse>
std::string refusal(const Refuse& refuse) {
  return mcrt::testing::message_of<UsageError>(refuse);
}

TEST(RayLimitTest, AcceptsUpToTheLimitAndRefusesJustAboveIt) {
  const double limit = 2e9;
  auto check = [&](double rays) {
    return refusal([&] {
      mcrt::check_ray_limit({rays, "rays"}, limit, "--spp", 2, "lower --spp");
    });
  };
  EXPECT_EQ(check(0.0), "");
  EXPECT_EQ(check(limit), "");  // the limit itself is allowed
  EXPECT_NE(check(std::nextafter(limit, 2.0 * limit)), "");
  EXPECT_NE(check(1.01 * limit), "");
  EXPECT_NE(check(std::numeric_limits<double>::infinity()), "");
}

TEST(RayLimitTest, RefusalIsOneLineWithTheCountTheTimeAndTheRemedy) {
  // 1e10 rays at 2.5e6 rays/s per thread on 2 threads: 2000 s, about 33 minutes.
  const std::string message = refusal([] {
    mcrt::check_ray_limit({1e10, "renders x spp x pixels"}, 1e9, "--spp, --width", 2,
                          "lower --spp");
  });
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_LT(message.size(), 200u) << message;
  EXPECT_EQ(message.rfind("--spp, --width: about 1e+10 rays", 0), 0u) << message;
  EXPECT_NE(message.find("(~33 min on 2 threads)"), std::string::npos) << message;
  EXPECT_NE(message.find("over the limit of 1e+09"), std::string::npos) << message;
  EXPECT_NE(message.find("lower --spp"), std::string::npos) << message;
}

// The furnace's albedo, refused in one place for every chapter: below 1 accepted, 1 and above
// (an infinite radiance, paths that never end) refused with one line naming --albedo.
TEST(RayLimitTest, FurnaceAlbedoBelowOneOnly) {
  auto check = [](double albedo) { return refusal([&] { mcrt::check_furnace_albedo(albedo); }); };
  EXPECT_EQ(check(0.0), "");
  EXPECT_EQ(check(std::nextafter(1.0, 0.0)), "");
  EXPECT_EQ(check(1.0).rfind("--albedo: give an albedo below 1", 0), 0u) << check(1.0);
  EXPECT_EQ(check(1.0).find('\n'), std::string::npos);
  EXPECT_NE(check(1.5), "");
  EXPECT_NE(check(std::numeric_limits<double>::infinity()), "");
}

TEST(WorkLimitTest, AcceptsUpToTheLimitAndRefusesJustAboveIt) {
  const double limit = 1e12;
  auto check = [&](double points) {
    return refusal([&] {
      mcrt::check_work_limit({points, "points", "trials x N"}, limit, "--trials", "lower --trials");
    });
  };
  EXPECT_EQ(check(limit), "");
  EXPECT_NE(check(std::nextafter(limit, 2.0 * limit)), "");
  const std::string message = check(3e12);
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_NE(message.find("--trials"), std::string::npos) << message;
  EXPECT_NE(message.find("3e+12 points"), std::string::npos) << message;
  EXPECT_NE(message.find("lower --trials"), std::string::npos) << message;
}

}  // namespace
