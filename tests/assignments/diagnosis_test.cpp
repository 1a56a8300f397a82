// The graders' diagnoses name the right bug: each known-wrong variant of tests/known_bugs/ run
// through an assignment's grading procedure fails it, with the diagnosis written for that bug.
// (CTest label assignments, and the default suite: about 3 s of CPU, 7 s wall on 2 loaded cores.)

#include <gtest/gtest.h>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/a2/a2_checks.hpp"
#include "assignments/a3/a3_checks.hpp"
#include "assignments/a4/a4_checks.hpp"
#include "assignments/a5/a5_checks.hpp"
#include "assignments/a6/a6_checks.hpp"
#include "assignments/a6/a6_produce.hpp"
#include "assignments/known_wrong_producers.hpp"
#include "assignments/subject/subject.hpp"
#include "known_bugs/a6_mis.hpp"
#include "known_bugs/assignments.hpp"
#include "known_bugs/disk_area.hpp"
#include "known_bugs/estimators.hpp"
#include "known_bugs/importance_sampling.hpp"
#include "known_bugs/nee.hpp"
#include "known_bugs/path_tracers.hpp"
#include "known_bugs/russian_roulette.hpp"
#include "known_bugs/samplers.hpp"
#include "stats/report.hpp"

namespace mcrt::testing::assignment {
namespace {

void expect_diagnosis(const TaskResult& r, const std::string& words) {
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_NE(r.message.find("DIAGNOSIS: " + words), std::string::npos) << r.message;
}

class Diagnoses : public ::testing::Test {
 protected:
  void SetUp() override { set_failure_reports(false); }
  void TearDown() override { set_failure_reports(true); }
};

TEST_F(Diagnoses, FalseFailureRateIsBelowOneInAMillion) {
  EXPECT_LT(majority_false_failure_rate(), 1e-6);
}

TEST_F(Diagnoses, A1DiskWithoutTheFactorFour) {
  expect_diagnosis(check_disk_estimator(with_disk([](std::uint64_t n, Rng& rng) { return estimate_disk_area(n, rng) / 4.0; })),
                   "your estimate is about pi/4: you forgot the factor 4");
}

TEST_F(Diagnoses, A1DiskWithYEqualToX) {
  expect_diagnosis(check_disk_estimator(with_disk(disk_area_same_coordinate_twice)), "your estimate is 4/sqrt(2)");
}

TEST_F(Diagnoses, A1BallHalfScale) {
  expect_diagnosis(check_ball_estimator(with_ball([](int, std::uint64_t n, Rng& rng) { return ball_volume_half_scale(n, rng); }), {3}),
                   "your volume is half of V_k");
}

TEST_F(Diagnoses, A1MonteCarloWithoutTheLength) {
  expect_diagnosis(check_basic_estimator(with_basic([](const auto& f, const Segment& s, std::uint64_t n, Rng& rng) {
                     MonteCarloEstimate e = monte_carlo(f, s, n, rng);
                     e.estimate = monte_carlo_without_volume(f, s, n, rng);
                     return e;
                   })),
                   "your mean is 0.33x the expected value: is the length (b - a)");
}

TEST_F(Diagnoses, A1TrapezoidWithFullEndWeights) {
  expect_diagnosis(check_trapezoid(with_rule([](const auto&, const Segment&, std::uint64_t n) {
                     return trapezoid_with_full_end_weights(Gaussian1D{}, n);
                   })),
                   "your error falls as h, not h^2");
}

double cosine_density(const Vec3& w) { return cosine_hemisphere_pdf(w.z); }
double uniform_density(const Vec3&) { return uniform_hemisphere_pdf(); }
double disk_density(const Vec2&) { return uniform_disk_pdf(); }

TEST_F(Diagnoses, A2UniformHemisphereThatIsCosine) {
  expect_diagnosis(check_sampler(each(sample_cosine_hemisphere), each(uniform_density), sampler_hemisphere_binning(),
                                 SamplerKind::uniform_hemisphere, "diagnosis_cosine_as_uniform"),
                   "observed/expected ~ 2 cos(theta): your samples look cosine-distributed");
}

TEST_F(Diagnoses, A2CosineHemisphereThatIsUniform) {
  expect_diagnosis(check_sampler(each(sample_uniform_hemisphere), each(cosine_density), sampler_hemisphere_binning(),
                                 SamplerKind::cosine_hemisphere, "diagnosis_uniform_as_cosine"),
                   "observed/expected ~ 1 / (2 cos(theta))");
}

TEST_F(Diagnoses, A2CosineHemisphereWithRadiusU) {
  expect_diagnosis(check_sampler(each(cosine_hemisphere_with_radius_u), each(cosine_density), sampler_hemisphere_binning(),
                                 SamplerKind::cosine_hemisphere, "diagnosis_cosine_radius_u"),
                   "half the expected samples near the horizon and too many near the pole: is the disk point "
                   "at r = u0");
}

TEST_F(Diagnoses, A2RightSamplerWrongPdf) {
  // the sampler is right; its chi-square fails only through the pdf, and says so
  expect_diagnosis(check_sampler(each(sample_cosine_hemisphere), each(cosine_pdf_times_two), sampler_hemisphere_binning(),
                                 SamplerKind::cosine_hemisphere, "diagnosis_wrong_pdf"),
                   "your pdf integrates to 2.000, not 1, and this test compares your samples with it: fix the pdf first");
}

TEST_F(Diagnoses, A2DiskWithRadiusU) {
  expect_diagnosis(check_sampler(each(disk_with_radius_u), each(disk_density), sampler_disk_binning(), SamplerKind::unit_disk,
                                 "diagnosis_disk_radius_u"),
                   "points crowd the centre");
}

TEST_F(Diagnoses, A2PdfsOffByTwo) {
  expect_diagnosis(check_pdf_integral(each(hemisphere_pdf_one_over_pi), sampler_hemisphere_binning(), "1/pi"),
                   "a pdf integrates to 1: yours is 2.000x too large (is it off by a factor of 2");
  expect_diagnosis(check_pdf_integral(each(cosine_pdf_times_two), sampler_hemisphere_binning(), "2 cos/pi"),
                   "a pdf integrates to 1: yours is 2.000x too large");
}

TEST_F(Diagnoses, A3RecursionOneBounceLate) {
  expect_diagnosis(check_ray_counts(a3_producer(incident_radiance_one_bounce_late)), "ray count is N^(k+1)");
  expect_diagnosis(check_recursive_furnace(a3_producer(incident_radiance_one_bounce_late)), "your mean is that of depth k + 1");
}

TEST_F(Diagnoses, A3RecursionOneBounceEarly) {
  const TaskResult r = check_ray_counts(a3_producer(incident_radiance_one_bounce_early));
  EXPECT_NE(r.message.find("DIAGNOSIS: ray count is N^k = 8 too few"), std::string::npos) << r.message;
}

TEST_F(Diagnoses, A3WithoutOneOverN) {
  expect_diagnosis(check_recursive_furnace(a3_producer(incident_radiance_without_one_over_n)), "each level weighs N a instead of a");
}

TEST_F(Diagnoses, A3BranchesSharingOneDirection) {
  expect_diagnosis(check_recursive_furnace(a3_producer(incident_radiance_one_shared_direction)),
                   "the mean is right but the variance is");
}

TEST_F(Diagnoses, A4MissingCosine) {
  expect_diagnosis(check_path_furnace(furnace_of(path_radiance_without_cosine)), "the per-bounce weight averages 2a instead of a and never varies: is the cosine missing?");
}

TEST_F(Diagnoses, A4SpherePdf) {
  expect_diagnosis(check_path_furnace(furnace_of(path_radiance_with_sphere_pdf)), "the per-bounce weight averages 2a instead of a: is your pdf off");
}

TEST_F(Diagnoses, A4CosineDirectionsUniformPdf) {
  expect_diagnosis(check_path_furnace(furnace_of(path_radiance_cosine_directions_uniform_pdf)), "the per-bounce weight averages 4a/3");
  EXPECT_FALSE(check_reference_regions(sky_of(path_radiance_cosine_directions_uniform_pdf)).passed);
}

TEST_F(Diagnoses, A5RouletteWithoutDividingByQ) {
  expect_diagnosis(check_roulette_furnace(with_roulette(roulette_without_division)), "your mean is 0.944x the expected value, that of roulette whose survivors keep their weight: is the survivor's weight divided by q?");
}

TEST_F(Diagnoses, A5RouletteBeforeTheEmission) {
  expect_diagnosis(check_roulette_furnace(with_roulette(roulette_before_emission)), "your mean is 0.927x the expected value: a path stopped at x_j loses Le(x_j)");
}

TEST_F(Diagnoses, A5RouletteFromVertexZero) {
  expect_diagnosis(check_roulette_furnace(with_roulette(roulette_from_depth_zero)), "paths trace 3.34 rays on average instead of d + 1/(1 - q) = 5.33: does the roulette start at vertex min_depth");
}

TEST_F(Diagnoses, A5CosinePdfWithoutOneOverPi) {
  expect_diagnosis(check_cosine_furnace_is_exact(with_importance(ignoring_the_pdf(path_radiance_cosine_pdf_without_inv_pi))),
                   "the per-bounce weight is a/pi instead of a, at every bounce: is the cosine pdf missing its 1/pi");
}

TEST_F(Diagnoses, A5CosineDirectionsUniformPdf) {
  expect_diagnosis(check_cosine_furnace_is_exact(with_importance(ignoring_the_pdf(path_radiance_cosine_directions_uniform_pdf))),
                   "the per-bounce weight averages 4a/3 and varies");
}

TEST_F(Diagnoses, A5NeeEmissionTwice) {
  expect_diagnosis(check_nee_furnace_is_exact(with_nee(with_path_end(nee_emission_twice))),
                   "direct light is 2x: is emission counted by both the light sample and the BSDF ray?");
  EXPECT_FALSE(check_nee_regions(with_nee(with_path_end(nee_emission_twice))).passed);
}

TEST_F(Diagnoses, A5NeeWithoutTheJacobian) {
  expect_diagnosis(check_nee_furnace_is_exact(with_nee(with_path_end(nee_without_jacobian))),
                   "direct light is 2.70x and varies from path to path; every light sample here should give exactly a Le: is p_A converted to solid angle");
  EXPECT_FALSE(check_nee_regions(with_nee(with_path_end(nee_without_jacobian))).passed);
}

TEST_F(Diagnoses, A5NeeCapOnly) {
  expect_diagnosis(check_nee_light_beyond_cap(with_nee(with_path_end(nee_cap_only))),
                   "almost no light reaches this wall through your shadow rays, though the light is in plain view: do you sample only the cap");
}

TEST_F(Diagnoses, A5NeeWithoutOneOverNLights) {
  // one light: nothing to see; two: the diagnosis names the 1/N
  EXPECT_TRUE(check_nee_regions(with_nee(with_path_end(nee_without_one_over_n_lights))).passed);
  const TaskResult r = check_nee_two_lights(with_nee(with_path_end(nee_without_one_over_n_lights)));
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_NE(r.message.find("DIAGNOSIS: region"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("does the light sample's pdf include the 1/N_lights"), std::string::npos) << r.message;
}

TEST_F(Diagnoses, A5NeeShadowRayHitsTheLight) {
  expect_diagnosis(check_nee_furnace_is_exact(with_nee(with_path_end(nee_shadow_ray_hits_light))),
                   "direct light is 0.00x: almost no shadow ray reaches the light");
}


// ---------------------------------------------------------------- a6
// The known-wrong variants are in known_bugs/a6_mis.hpp.

TEST_F(Diagnoses, A6SolutionPasses) {
  const A6Variant<> solution;
  EXPECT_TRUE(check_lobe_sampler(solution).passed);
  EXPECT_TRUE(check_sharp_lobe_digits(solution).passed);
  EXPECT_TRUE(check_heuristic(solution, A6Heuristic::power).passed);
  EXPECT_TRUE(check_mis_regions(solution, A6Strategy::mis_power).passed);
}

TEST_F(Diagnoses, A6LobeCosineToOneOverM) {
  expect_diagnosis(check_lobe_sampler(with_lobe(lobe_cosine_to_one_over_m)), "the mean cos(alpha) is");
}

TEST_F(Diagnoses, A6LobeHalfTheAzimuths) {
  expect_diagnosis(check_lobe_sampler(with_lobe(lobe_half_the_azimuths)), "almost no direction has y < 0");
}

TEST_F(Diagnoses, A6LobeSineFromOneMinusCosSquared) {
  const auto cancelling = lobe_sine_from_one_minus_cos_squared;
  EXPECT_TRUE(check_lobe_sampler(with_lobe(cancelling)).passed) << "the distribution is right at m = 10";
  expect_diagnosis(check_sharp_lobe_digits(with_lobe(cancelling)), "sin(alpha) lost its digits");
}

TEST_F(Diagnoses, A6LobePdfWithTheBrdfsNormalisation) {
  const auto m_plus_2 = lobe_pdf_with_the_brdfs_normalisation;
  expect_diagnosis(check_lobe_pdf_integral(with_lobe_pdf(m_plus_2)), "your pdf is (m + 2)/(m + 1) too large");
  // the correct sampler fails against the wrong pdf, and is told to fix the pdf first
  expect_diagnosis(check_lobe_sampler(with_lobe_pdf(m_plus_2)), "your pdf integrates to 1.091, not 1");
}

TEST_F(Diagnoses, A6LobePdfRoundTheNormal) {
  expect_diagnosis(check_lobe_pdf_round_mirror(with_lobe_pdf(lobe_pdf_round_the_normal)), "your pdf uses w.z");
}

TEST_F(Diagnoses, A6PowerHeuristicNotSquared) {
  expect_diagnosis(check_heuristic(with_weight(power_heuristic_not_squared), A6Heuristic::power),
                   "your power heuristic gives the balance heuristic's weights");
}

TEST_F(Diagnoses, A6HeuristicWithoutTheGuard) {
  expect_diagnosis(check_heuristic(with_weight(heuristic_without_the_guard), A6Heuristic::balance),
                   "a weight is NaN");
}

TEST_F(Diagnoses, A6WeightsThatDoNotSumToOne) {
  expect_diagnosis(check_heuristic(with_weight(weights_that_do_not_sum_to_one), A6Heuristic::power),
                   "the weights of one direction must sum to 1");
}

TEST_F(Diagnoses, A6BsdfHitWeightedAsIfByNee) {
  expect_diagnosis(check_mis_regions(with_mis(mis_bsdf_hit_weighted_as_if_by_nee()), A6Strategy::mis_balance),
                   "the BSDF sample is weighted as if it were the light sample");
}

TEST_F(Diagnoses, A6BsdfHitNotWeighted) {
  expect_diagnosis(check_mis_regions(with_mis(mis_bsdf_hit_not_weighted()), A6Strategy::mis_power),
                   "light is counted twice where light sampling wins: the BSDF sample that hits a light is added with weight 1");
}

TEST_F(Diagnoses, A6LightSampleNotWeighted) {
  expect_diagnosis(check_mis_regions(with_mis(mis_light_sample_not_weighted()), A6Strategy::mis_power),
                   "light is counted twice where BSDF sampling wins");
}

TEST_F(Diagnoses, A6LightPdfPerUnitArea) {
  expect_diagnosis(check_mis_regions(with_mis(&mis_light_pdf_per_unit_area), A6Strategy::mis_balance),
                   "some regions are off by a large factor: are both pdfs of a weight in the same measure?");
}

TEST_F(Diagnoses, A6LightSamplingPassedOffAsMis) {
  // unbiased (the region tests pass), but no better than light sampling alone
  EXPECT_TRUE(check_mis_regions(light_sampling_as_mis(), A6Strategy::mis_balance).passed);
  expect_diagnosis(check_mis_efficiency(light_sampling_as_mis(), A6Strategy::mis_balance),
                   "in region plate 3 x light 3 MIS is");
}

// The a6 reference table (k_a6_reference): run by hand with --gtest_also_run_disabled_tests.
TEST(A6Reference, DISABLED_PrintReference) {
  constexpr int spp = 16384;
  const std::vector<RunningStats> s = a6_region_stats(
      a6_region_samples(&student_mis, A6Strategy::mis_power, k_a6_width, k_a6_height, spp, 0x5eed6ULL), spp);
  const std::vector<PlateRegion> regions = plate_regions(make_veach_plates(), k_a6_width, k_a6_height);
  for (std::size_t r = 0; r < s.size(); ++r)
    std::printf("    {%.17g, %.17g},  // plate %zu, light %zu: %d pixels\n", s[r].mean(),
                std::sqrt(s[r].variance() / static_cast<double>(s[r].count())), regions[r].plate, regions[r].light,
                regions[r].pixel_count());
}

}  // namespace
}  // namespace mcrt::testing::assignment
