// Chapter 07's samplers and its importance-sampled path tracer
// (common/sampling/cosine_power.hpp, common/render/importance_path_tracer.hpp):
//  - every new sampler against its own pdf (chi-square, stats/sampler_tests.hpp), and every pdf
//    integrates to 1;
//  - the furnace: with the cosine pdf every path is exactly Le (1 - a^(k+1)) / (1 - a) (zero
//    variance); with the pdfs of finite variance the mean is that closed form (z-tests);
//  - two parallel plates, where every pdf has a finite variance: the mean agrees with chapter
//    05's path tracer for every pdf (two-sample z-tests).
// Every statistical check is designed for a false-failure rate alpha = 1e-4 (the furnace ones
// up to about 1.5e-4: see there).

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "render/importance_path_tracer.hpp"
#include "sampling/cosine_power.hpp"
#include "stats/check.hpp"
#include "stats/chi_square.hpp"
#include "stats/hypothesis.hpp"
#include "stats/sampler_tests.hpp"
#include "render/path_tracer_furnace.hpp"
#include "render/importance_path_tracer_plates.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

// ---------------------------------------------------------------------------------------------
// Samplers. Streams of their own, 200 + m for cos^m and 210 for the grazing pdf, apart from
// the other sampler checks' 1-5 and 100-109 (sampler_tests.hpp), so all are independent.

constexpr std::uint64_t k_cosine_power_stream = 200;  // + m
constexpr std::uint64_t k_grazing_hemisphere_stream = 210;

double cosine_power_p_value(std::uint64_t seed, int m) {
  const std::string name = "cosine_power_sampler_matches_its_pdf_m" + std::to_string(m);
  return hemisphere_sampler_p_value([m](Vec2 u) { return sample_cosine_power_hemisphere(u, m); },
                                    [m](const Vec3& w) {
                                      return cosine_power_hemisphere_pdf(w.z, m);
                                    },
                                    seed, k_cosine_power_stream + static_cast<std::uint64_t>(m),
                                    name);
}

MCRT_STATISTICAL_CHECK(cosine_power_sampler_matches_its_pdf_m0, k_sampler_alpha) {
  return cosine_power_p_value(seed, 0);
}
MCRT_STATISTICAL_CHECK(cosine_power_sampler_matches_its_pdf_m1, k_sampler_alpha) {
  return cosine_power_p_value(seed, 1);
}
MCRT_STATISTICAL_CHECK(cosine_power_sampler_matches_its_pdf_m2, k_sampler_alpha) {
  return cosine_power_p_value(seed, 2);
}
MCRT_STATISTICAL_CHECK(cosine_power_sampler_matches_its_pdf_m4, k_sampler_alpha) {
  return cosine_power_p_value(seed, 4);
}
MCRT_STATISTICAL_CHECK(cosine_power_sampler_matches_its_pdf_m8, k_sampler_alpha) {
  return cosine_power_p_value(seed, 8);
}
MCRT_STATISTICAL_CHECK(grazing_hemisphere_sampler_matches_its_pdf, k_sampler_alpha) {
  return hemisphere_sampler_p_value(
      sample_grazing_hemisphere, [](const Vec3& w) { return grazing_hemisphere_pdf(w.z); }, seed,
      k_grazing_hemisphere_stream, "grazing_hemisphere_sampler_matches_its_pdf");
}

// The pdfs integrate to 1. cos^m is a polynomial of degree m <= 8 in cos(theta) on each cell,
// which 15-point Gauss-Kronrod integrates exactly: 1e-9 is round-off room, as for the other
// samplers. The grazing pdf sqrt(1 - z^2) has an infinite slope at z = 1 (the top row of
// cells), where the adaptive quadrature stops at its tolerance 1e-10 per cell: 1e-7 is far
// above that and far below any error in a constant.
TEST(CosinePowerPdfTest, EveryPdfIntegratesToOne) {
  for (int m : {0, 1, 2, 3, 4, 8, 16})
    EXPECT_NEAR(pdf_integral([m](const Vec3& w) { return cosine_power_hemisphere_pdf(w.z, m); },
                             sampler_hemisphere_binning()),
                1.0, 1e-9)
        << "m = " << m;
  EXPECT_NEAR(pdf_integral([](const Vec3& w) { return grazing_hemisphere_pdf(w.z); },
                           sampler_hemisphere_binning()),
              1.0, 1e-7);
}

// ---------------------------------------------------------------------------------------------
// Furnace. With the cosine pdf the weight of every bounce is a (to round-off), so every path
// returns the closed form: 1e-12 relative is a few roundings per bounce of numbers near 1.
constexpr double k_cosine_furnace_tolerance = 1e-12;

TEST(ImportanceFurnaceTest, CosinePdfHasZeroVariance) {
  for (const FurnaceSetup& setup : {FurnaceSetup{0.5, 1.0, 4}, FurnaceSetup{0.6, 1.0, 5},
                                    FurnaceSetup{0.9, 2.0, 20}, FurnaceSetup{0.99, 0.5, 50}}) {
    EXPECT_LE(furnace_largest_relative_deviation(setup, 2000, k_suite_seed, 40,
                                                 importance_tracer(cosine_power_pdf(1))),
              k_cosine_furnace_tolerance)
        << "albedo " << setup.albedo << " depth " << setup.depth;
    EXPECT_NEAR(furnace_radiance_variance(cosine_power_pdf(1), setup.albedo, setup.emission,
                                          setup.depth),
                0.0, 1e-12);
  }
}

// The mean, for the pdfs of finite variance (m = 0, 2 and grazing; m >= 3 is infinite, tested
// on the plates below), with the closed-form standard error. cos^2 and the grazing pdf have a
// heavy tail, P(w > t) = C t^-3 (C = (2a/3)^3 and a^3 pi^2 / 6): one sample alone can push the
// mean past the z-test's 3.9 standard errors, with probability about n C (3.9 sigma sqrt n)^-3
// = C / (59 sigma^3 sqrt n), 4e-5 at n = 4e5 and a = 0.5 for either. So these checks fail on
// right code at up to about 1.5e-4, not 1e-4. n = 4e5 paths of depth 2 take ~0.2 s.
constexpr int k_furnace_paths = 400000;

double furnace_mean_check(std::uint64_t seed, std::uint64_t block, const HemispherePdf& pdf) {
  const FurnaceSetup setup{0.5, 1.0, 2};
  return importance_furnace_mean_p_value(setup, pdf,
                                         furnace_samples(setup, k_furnace_paths, seed, block,
                                                         importance_tracer(pdf)));
}

MCRT_STATISTICAL_CHECK(importance_furnace_mean_uniform, 1e-4) {
  return furnace_mean_check(seed, 41, cosine_power_pdf(0));
}
MCRT_STATISTICAL_CHECK(importance_furnace_mean_cos2, 1e-4) {
  return furnace_mean_check(seed, 42, cosine_power_pdf(2));
}
MCRT_STATISTICAL_CHECK(importance_furnace_mean_grazing, 1e-4) {
  return furnace_mean_check(seed, 43, {HemispherePdf::grazing, 0});
}

// ---------------------------------------------------------------------------------------------
// Plates: against chapter 05's tracer, every pdf (render/importance_path_tracer_plates.hpp). 2e5 paths
// per side: the grazing pdf's weight has the same t^-3 tail near the normal, so more paths
// keep a single sample's push well below alpha (about 2e-5 here).
constexpr int k_plate_paths = 200000;

MCRT_STATISTICAL_CHECK(importance_matches_path_tracer_on_plates_uniform, 1e-4) {
  return plates_p_value(k_plate_paths, seed, 50, importance_tracer(cosine_power_pdf(0)));
}
MCRT_STATISTICAL_CHECK(importance_matches_path_tracer_on_plates_cosine, 1e-4) {
  return plates_p_value(k_plate_paths, seed, 51, importance_tracer(cosine_power_pdf(1)));
}
MCRT_STATISTICAL_CHECK(importance_matches_path_tracer_on_plates_cos2, 1e-4) {
  return plates_p_value(k_plate_paths, seed, 52, importance_tracer(cosine_power_pdf(2)));
}
MCRT_STATISTICAL_CHECK(importance_matches_path_tracer_on_plates_cos4, 1e-4) {
  return plates_p_value(k_plate_paths, seed, 53, importance_tracer(cosine_power_pdf(4)));
}
MCRT_STATISTICAL_CHECK(importance_matches_path_tracer_on_plates_cos8, 1e-4) {
  return plates_p_value(k_plate_paths, seed, 54, importance_tracer(cosine_power_pdf(8)));
}
MCRT_STATISTICAL_CHECK(importance_matches_path_tracer_on_plates_grazing, 1e-4) {
  return plates_p_value(k_plate_paths, seed, 55, importance_tracer({HemispherePdf::grazing, 0}));
}

}  // namespace
