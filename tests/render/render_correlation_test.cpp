// The correlation checks' procedures (tests/render/render_correlation.hpp) reject pixel loops whose
// streams are keyed wrongly (tests/render/render_correlation_known_bugs.hpp), at the sizes, seed and
// alpha of the checks in tests/render/render_correlation_checks.cpp; the right keying, through the
// same loop, passes beside them.

#include <gtest/gtest.h>

#include "render/render_correlation_known_bugs.hpp"
#include "stats/check.hpp"
#include "render/render_correlation.hpp"

using namespace mcrt;
namespace bugs = mcrt::testing::known_bugs;

namespace {

constexpr double k_albedo = 0.5, k_emission = 1.0, k_alpha = 1e-4;
constexpr int k_depth = 3;
const double k_mean = furnace_radiance(k_albedo, k_emission, k_depth);
const double k_variance = furnace_radiance_variance(k_albedo, k_emission, k_depth);

std::uint64_t right_key(std::uint64_t x, std::uint64_t y, std::uint64_t s) {
  return stream_index(y * 128 + x, s);
}

TEST(CorrelationProceduresTest, NeighbourCheckRejectsPixelsSharingStreams) {
  const Scene furnace = make_furnace(k_albedo, k_emission);
  const std::uint64_t seed = mcrt::testing::k_suite_seed;
  const auto right = bugs::furnace_pixels_keyed(furnace, 128, 128, k_depth, seed, 0, right_key);
  const auto wrong =
      bugs::furnace_pixels_keyed(furnace, 128, 128, k_depth, seed, 0, bugs::key_x_plus_y);
  EXPECT_GE(mcrt::testing::neighbour_correlation_p_value(right, 128, 128, k_mean, k_variance),
            k_alpha);
  EXPECT_LT(mcrt::testing::neighbour_correlation_p_value(wrong, 128, 128, k_mean, k_variance),
            k_alpha);
}

TEST(CorrelationProceduresTest, SampleCheckRejectsSamplesSharingStreams) {
  const Scene furnace = make_furnace(k_albedo, k_emission);
  const std::uint64_t seed = mcrt::testing::k_suite_seed;
  std::vector<std::vector<double>> right, wrong;
  for (std::uint64_t s = 0; s < 4; ++s) {
    right.push_back(bugs::furnace_pixels_keyed(furnace, 96, 96, k_depth, seed, s, right_key));
    wrong.push_back(
        bugs::furnace_pixels_keyed(furnace, 96, 96, k_depth, seed, s, bugs::key_ignoring_sample));
  }
  EXPECT_GE(mcrt::testing::sample_correlation_p_value(right, k_mean, k_variance), k_alpha);
  EXPECT_LT(mcrt::testing::sample_correlation_p_value(wrong, k_mean, k_variance), k_alpha);
}

}  // namespace
