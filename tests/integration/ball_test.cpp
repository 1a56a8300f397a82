// The unit k-ball (integration/ball.hpp): its volume against the closed forms for k = 0..12.

#include <gtest/gtest.h>

#include <cmath>

#include "integration/ball.hpp"

using namespace mcrt;

namespace {

TEST(BallVolumeTest, MatchesTheClosedFormsForKFrom0To12) {
  const double pi = k_pi;
  // V_2m = pi^m / m!,  V_2m+1 = 2^(m+1) pi^m / (2m+1)!!.
  const double expected[] = {1.0,
                             2.0,
                             pi,
                             4.0 * pi / 3.0,
                             pi * pi / 2.0,
                             8.0 * pi * pi / 15.0,
                             pi * pi * pi / 6.0,
                             16.0 * pi * pi * pi / 105.0,
                             std::pow(pi, 4) / 24.0,
                             32.0 * std::pow(pi, 4) / 945.0,
                             std::pow(pi, 5) / 120.0,
                             64.0 * std::pow(pi, 5) / 10395.0,
                             std::pow(pi, 6) / 720.0};
  for (int k = 0; k <= 12; ++k)
    // pow and tgamma are each within a few ulps: 1e-13 relative leaves room, and a wrong
    // formula (Gamma(k/2) instead of Gamma(k/2 + 1)) is off by a factor k/2.
    EXPECT_NEAR(unit_ball_volume(k), expected[k], 1e-13 * expected[k]) << "k = " << k;
  // The volume peaks at k = 5 and then falls towards 0.
  EXPECT_GT(unit_ball_volume(5), unit_ball_volume(4));
  EXPECT_GT(unit_ball_volume(5), unit_ball_volume(6));
}

}  // namespace
