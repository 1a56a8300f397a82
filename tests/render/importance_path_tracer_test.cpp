// Chapter 07's samplers and importance-sampled path tracer (common/sampling/cosine_power.hpp,
// common/render/importance_path_tracer.hpp): fixed inputs of the samplers, the closed forms of
// the furnace, the uniform pdf giving chapter 05's tracer bit for bit, and that the checks'
// procedures reject the known-wrong tracers of tests/render/importance_path_tracer_known_bugs.hpp.
// (Its statistical checks are in tests/render/importance_path_tracer_checks.cpp.)

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "render/importance_path_tracer_known_bugs.hpp"
#include "render/path_tracer_known_bugs.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/path_tracer.hpp"
#include "sampling/cosine_power.hpp"
#include "stats/check.hpp"
#include "render/importance_path_tracer_plates.hpp"

using namespace mcrt;

namespace {

const HemispherePdf k_grazing{HemispherePdf::grazing, 0};

TEST(CosinePowerTest, SamplesAreUnitDirectionsInTheUpperHemisphere) {
  Rng rng(1, 0);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 u = i < 4 ? Vec2(i % 2 ? 0.999999 : 0.0, i / 2 ? 0.999999 : 0.0) : rng.uniform2();
    for (const HemispherePdf& pdf : {cosine_power_pdf(0), cosine_power_pdf(1), cosine_power_pdf(2),
                                     cosine_power_pdf(8), k_grazing}) {
      const Vec3 w = sample_hemisphere(pdf, u);
      EXPECT_NEAR(glm::length(w), 1.0, 1e-12) << pdf_name(pdf);  // a few roundings
      EXPECT_GE(w.z, 0.0) << pdf_name(pdf);
      EXPECT_TRUE(std::isfinite(hemisphere_pdf(pdf, w.z)));
    }
  }
}

TEST(CosinePowerTest, InversionFormulasAtFixedInputs) {
  // cos^m: cos(theta) = u0^(1/(m+1)); m = 0 is the uniform sampler exactly.
  EXPECT_DOUBLE_EQ(sample_cosine_power_hemisphere({0.25, 0.0}, 1).z, 0.5);
  EXPECT_DOUBLE_EQ(sample_cosine_power_hemisphere({0.125, 0.0}, 2).z, 0.5);
  EXPECT_EQ(sample_cosine_power_hemisphere({0.3, 0.7}, 0), sample_uniform_hemisphere({0.3, 0.7}));
  // grazing: CDF of theta is (2 theta - sin 2 theta) / pi; at theta = pi/4 it is 1/2 - 1/pi.
  const double u_quarter = 0.5 - k_inv_pi;
  EXPECT_NEAR(std::acos(sample_grazing_hemisphere({u_quarter, 0.0}).z), k_pi / 4.0, 1e-12);
  for (double u0 : {1e-6, 0.01, 0.5, 0.9, 0.999999}) {  // Newton's root solves the CDF
    const double theta = std::acos(sample_grazing_hemisphere({u0, 0.0}).z);
    EXPECT_NEAR((2 * theta - std::sin(2 * theta)) * k_inv_pi, u0, 1e-12) << u0;
  }
  EXPECT_EQ(sample_grazing_hemisphere({0.0, 0.0}).z, 1.0);  // the normal: density 0
  // The smallest u0 > 0 of a 32-bit uniform: theta = (3 pi u0 / 4)^(1/3) = 0.0008.
  const Vec3 tiny = sample_grazing_hemisphere({0x1p-32, 0.0});
  EXPECT_GT(tiny.z, 0.99);
  EXPECT_LT(tiny.z, 1.0);
}

TEST(CosinePowerTest, PdfsAtFixedDirections) {
  EXPECT_DOUBLE_EQ(cosine_power_hemisphere_pdf(0.5, 0), k_inv_two_pi);
  EXPECT_DOUBLE_EQ(cosine_power_hemisphere_pdf(0.5, 1), 0.5 * k_inv_pi);
  EXPECT_DOUBLE_EQ(cosine_power_hemisphere_pdf(0.5, 4), 5.0 * k_inv_two_pi / 16.0);
  EXPECT_DOUBLE_EQ(grazing_hemisphere_pdf(0.0), 2.0 / (k_pi * k_pi));
  EXPECT_EQ(grazing_hemisphere_pdf(1.0), 0.0);
  EXPECT_EQ(pdf_name(cosine_power_pdf(0)), "uniform");
  EXPECT_EQ(pdf_name(cosine_power_pdf(1)), "cosine");
  EXPECT_EQ(pdf_name(cosine_power_pdf(4)), "cos^4");
  EXPECT_EQ(pdf_name(k_grazing), "grazing");
}

TEST(ImportancePathTracerTest, UniformPdfIsChapter05BitForBit) {
  const Scene scene = make_cornell_box();
  const Camera camera(scene.camera, 12, 9);
  for (std::uint64_t s = 0; s < 300; ++s) {
    Rng rng_a(3, s), rng_b(3, s);
    RayCount a, b;
    const Ray ray = camera.generate_ray(12 * rng_a.uniform(), 9 * rng_a.uniform());
    rng_b.uniform2();
    EXPECT_EQ(estimate_importance_path_radiance(scene, ray, 6, cosine_power_pdf(0), rng_a, a),
              estimate_path_radiance(scene, ray, 6, rng_b, b));
    EXPECT_EQ(a.rays, b.rays);
  }
}

TEST(ImportancePathTracerTest, FurnaceClosedForms) {
  const double a = 0.6;
  // One bounce: Var[L] = Le^2 (b - a^2).
  EXPECT_NEAR(furnace_radiance_variance(cosine_power_pdf(0), a, 2.0, 1),
              furnace_radiance_variance(a, 2.0, 1), 1e-12);  // chapter 05's, uniform
  EXPECT_NEAR(furnace_radiance_variance(cosine_power_pdf(0), a, 1.0, 7),
              furnace_radiance_variance(a, 1.0, 7), 1e-12);
  EXPECT_NEAR(furnace_radiance_variance(cosine_power_pdf(2), a, 1.0, 1), 4 * a * a / 3 - a * a,
              1e-12);
  EXPECT_NEAR(furnace_radiance_variance(k_grazing, a, 1.0, 1), (k_pi * k_pi / 4 - 1) * a * a,
              1e-12);
  EXPECT_NEAR(furnace_radiance_variance(cosine_power_pdf(1), a, 1.0, 30), 0.0, 1e-12);
  EXPECT_TRUE(std::isinf(furnace_radiance_variance(cosine_power_pdf(3), a, 1.0, 1)));
  EXPECT_TRUE(std::isinf(furnace_radiance_variance(cosine_power_pdf(8), a, 1.0, 4)));
  EXPECT_EQ(furnace_radiance_variance(cosine_power_pdf(8), a, 1.0, 0), 0.0);
  EXPECT_EQ(furnace_bounce_second_moment(cosine_power_pdf(8), 0.0), 0.0);
  // b for cos^m, m = 2: integral of (a z / pi)^2 / (3 z^2 / (2 pi)) over the hemisphere =
  // 2 pi (2 a^2 / (3 pi)) = 4 a^2 / 3, as for uniform.
  EXPECT_DOUBLE_EQ(furnace_bounce_second_moment(cosine_power_pdf(2), a), 4 * a * a / 3);
}

// Known-wrong tracers: both procedures of the checks, at the checks' sizes, seed, streams and
// alpha, must reject each (and pass the right tracer at this seed).
TEST(ImportancePathTracerTest, ChecksRejectKnownWrongTracers) {
  using namespace mcrt::testing;
  const FurnaceSetup setup{0.5, 1.0, 4};
  const auto furnace_deviation = [&](auto tracer) {
    return furnace_largest_relative_deviation(setup, 2000, k_suite_seed, 40, tracer);
  };
  const auto plates = [](auto tracer) {
    return plates_p_value(200000, k_suite_seed, 51, tracer);  // block of the cosine check
  };
  EXPECT_LE(furnace_deviation(importance_tracer(cosine_power_pdf(1))), 1e-12);
  EXPECT_GE(plates(importance_tracer(cosine_power_pdf(1))), 1e-4);
  for (const auto& wrong :
       {path_radiance_cosine_pdf_without_inv_pi, path_radiance_dividing_by_cosine_twice,
        path_radiance_cosine_directions_uniform_pdf}) {
    EXPECT_GT(furnace_deviation(wrong), 1e-3);
    EXPECT_LT(plates(wrong), 1e-4);
  }
}

}  // namespace
