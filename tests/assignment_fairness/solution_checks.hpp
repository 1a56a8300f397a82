#pragma once
// Every p-value-based check of the assignments a1-a7 on the solution (LocalSubject: the
// tree's own functions, in this process), each through the per-seed function its test calls
// at the grading seeds (tests/assignments/aN/aN_checks.hpp), so that what is measured is what
// grades. The hidden tests that are statistical come from tests/assignments/hidden/ when the
// tree has it (never in a kit).

#include <cstdint>
#include <vector>

#include "assignment_fairness/measured_check.hpp"
#include "assignments/a1/a1_checks.hpp"
#include "assignments/a2/a2_checks.hpp"
#include "assignments/a3/a3_checks.hpp"
#include "assignments/a4/a4_checks.hpp"
#include "assignments/a5/a5_checks.hpp"
#include "assignments/a6/a6_checks.hpp"
#include "assignments/a6/a6_dielectric_checks.hpp"
#include "assignments/a7/a7_checks.hpp"
#include "assignments/subject/subject.hpp"
#include "sampling/cosine_power.hpp"

#if __has_include("assignments/hidden/fairness_p_values.hpp")
#include "assignments/hidden/fairness_p_values.hpp"
#define MCRT_FAIRNESS_HIDDEN 1
#endif

namespace mcrt::testing::assignment {

/// a2's chi-square of sampler `kind` at one seed: its cell probabilities from the subject's
/// pdf, computed once (as check_sampler does before its seeds).
template <class Point>
MeasuredCheck sampler_check(const char* name, const char* test, SamplerKind kind,
                            const Binning<Point>& binning) {
  const std::vector<double> probability =
      bulk_cell_probabilities(pdf_of<Point>(subject(), kind), binning);
  return {name, test, k_seed_alpha, true, false, [=](std::uint64_t seed) {
            return sampler_chi_square(samples_of<Point>(subject(), kind), probability, binning,
                                      seed)
                .p_value;
          }};
}

inline std::vector<MeasuredCheck> solution_checks() {
  LocalSubject& s = subject();
  std::vector<MeasuredCheck> checks{{"a1_disk", "a1.A1.Task1DiskEstimateIsUnbiased", k_seed_alpha,
                                     true, false, [&s](std::uint64_t seed) {
                                       double a = 0.0;
                                       return disk_p_value(s, seed, a);
                                     }}};
  checks.push_back({"a1_ball", "a1.A1.Task2BallVolumesAreUnbiased", k_seed_alpha, true, false,
                    [&s](std::uint64_t seed) {  // the dimensions a1's test checks, one verdict
                      std::vector<double> sums;
                      return balls_p_value(s, {2, 3, 5}, seed, sums);
                    }});
  checks.push_back({"a1_basic_estimator", "a1.A1.Task3BasicEstimatorIsUnbiasedWithItsStandardError",
                    k_seed_alpha, true, false, [&s](std::uint64_t seed) {
                      EstimateAndError e;
                      return basic_estimator_p_value(s, seed, e);
                    }});
  checks.push_back(sampler_check("a2_uniform_hemisphere",
                                 "a2.A2.Task1UniformHemisphereFollowsItsPdf",
                                 SamplerKind::uniform_hemisphere, sampler_hemisphere_binning()));
  checks.push_back(sampler_check("a2_cosine_hemisphere", "a2.A2.Task2CosineHemisphereFollowsItsPdf",
                                 SamplerKind::cosine_hemisphere, sampler_hemisphere_binning()));
  checks.push_back(sampler_check("a2_uniform_sphere", "a2.A2.Task3UniformSphereFollowsItsPdf",
                                 SamplerKind::uniform_sphere, sphere_binning(21, 21)));
  checks.push_back(sampler_check("a2_unit_disk", "a2.A2.Task4UnitDiskFollowsItsPdf",
                                 SamplerKind::unit_disk, sampler_disk_binning()));
  checks.push_back(sampler_check("a2_uniform_cone", "a2.A2.Task5UniformConeFollowsItsPdf",
                                 SamplerKind::uniform_cone, sampler_cone_binning()));
  checks.push_back({"a3_furnace", "a3.A3.Task1FurnaceMeanAndVarianceMatchTheClosedForms",
                    k_seed_alpha, true, false, [&s](std::uint64_t seed) {
                      RunningStats r;
                      return recursive_furnace_p_value(s, seed, r);
                    }});
  checks.push_back({"a4_furnace", "a4.A4.Task1FurnaceMeanAndVarianceMatchTheClosedForms",
                    k_seed_alpha, true, false, [&s](std::uint64_t seed) {
                      double m = 0.0;
                      return path_furnace_p_value(furnace_of_subject(s), seed, m);
                    }});
  checks.push_back({"a4_regions", "a4.A4.Task1RegionsAgreeWithTheReference", k_seed_alpha, true,
                    true, [&s](std::uint64_t seed) {
                      int worst = 0;
                      double z = 0.0;
                      return reference_regions_p_value(sky_of_subject(s), seed, worst, z);
                    }});
  // a4.2: the pixel's jitter (chi-square over the pixel's cells) and its standard error's calibration
  checks.push_back({"a4_pixel_jitter", "a4.A4.Task2JitterCoversThePixelUniformly", k_seed_alpha,
                    true, false, [&s](std::uint64_t seed) {
                      bool centred = false;
                      return jitter_p_value(pixel_rays_of_subject(s), seed, centred);
                    }});
  checks.push_back({"a4_pixel_calibration", "a4.A4.Task2StandardErrorIsCalibrated", k_seed_alpha,
                    true, false, [&s](std::uint64_t seed) {
                      double z_variance = 0.0;
                      return calibration_p_value(pixel_furnace_of_subject(s), seed, z_variance);
                    }});
  checks.push_back({"a5_roulette_furnace", "a5.A5.Task1RouletteFurnaceMatchesTheClosedForms",
                    k_seed_alpha, true, false, [&s](std::uint64_t seed) {
                      double mean = 0.0, rays = 0.0;
                      return roulette_furnace_p_value(s, seed, mean, rays);
                    }});
  checks.push_back({"a5_uniform_furnace", "a5.A5.Task2UniformFurnaceMeanAndVariance", k_seed_alpha,
                    true, false, [&s](std::uint64_t seed) {
                      double m = 0.0;
                      return importance_furnace_p_value(s, cosine_power_pdf(0), seed, m);
                    }});
  checks.push_back({"a5_cos2_furnace", "a5.A5.Task2CosineSquaredFurnaceMean", k_seed_alpha, true,
                    false, [&s](std::uint64_t seed) {
                      double m = 0.0;
                      return importance_furnace_p_value(s, cosine_power_pdf(2), seed, m);
                    }});
  for (int parts : {1, 2})
    checks.push_back({parts == 1 ? "a5_nee_regions" : "a5_nee_two_lights",
                      parts == 1 ? "a5.A5.Task3RegionsAgreeWithThePathTracer"
                                 : "a5.A5.Task3TwoLightsAgreeWithThePathTracer",
                      k_seed_alpha, true, true, [&s, parts](std::uint64_t seed) {
                        int worst = 0;
                        double z = 0.0, ratio = 1.0;
                        return nee_regions_p_value(s, seed, worst, z, ratio, parts);
                      }});
  checks.push_back({"a5_nee_beyond_cap", "a5.A5.Task3LightBeyondTheCapAgreesWithThePathTracer",
                    k_seed_alpha, true, false, [&s](std::uint64_t seed) {
                      double r = 1.0;
                      return nee_beyond_cap_p_value(s, seed, r);
                    }});
  // a6.1: the lobe's chi-square at m = 10, against the subject's pdf (computed once)
  checks.push_back({"a6_phong_lobe", "a6.A6.Task1LobeFollowsItsPdf", k_seed_alpha, true, false,
                    [&s, probability = bulk_cell_probabilities(lobe_pdf_of(s, k_a6_lobe_m),
                                                               sampler_hemisphere_binning())](
                        std::uint64_t seed) {
                      return chi_square_points_test(lobe_samples_at(s, k_a6_lobe_m, seed),
                                                    probability, sampler_hemisphere_binning())
                          .p_value;
                    }});
  // a6.3: MIS's 16 plate x light regions against the stored reference, either heuristic
  for (A6Strategy h : {A6Strategy::mis_balance, A6Strategy::mis_power})
    checks.push_back({h == A6Strategy::mis_balance ? "a6_balance_regions" : "a6_power_regions",
                      h == A6Strategy::mis_balance
                          ? "a6.A6.Task3BalanceRegionsAgreeWithTheReference"
                          : "a6.A6.Task3PowerRegionsAgreeWithTheReference",
                      k_seed_alpha, true, true, [&s, h](std::uint64_t seed) {
                        std::size_t worst = 0;
                        double z = 0.0;
                        return mis_regions_p_value(mis_region_stats_at(s, h, seed), worst, z);
                      }});
  // a6.4: the glass's reflected fractions against Fresnel's R (an invalid sample gives 0)
  checks.push_back({"a6_dielectric_branch", "a6.A6.Task4ReflectsInTheFresnelFraction", k_seed_alpha,
                    true, false, [&s](std::uint64_t seed) {
                      std::string wrong, table;
                      return dielectric_branch_p_value(s, seed, wrong, table);
                    }});
  // a7: a point's chi-square over randomisations (a7.1, a7.2, a7.4); jittered's variance ratio
  // is a threshold (measure_assignment_fairness.cpp's threshold rows)
  checks.push_back({"a7_jittered_uniform", "a7.A7.Task1JitteredPointIsUniform", k_seed_alpha, true,
                    false, [&s](std::uint64_t seed) {
                      return point_uniformity(s, A7PointSet::jittered, k_a7_grid * k_a7_grid, 2, 5,
                                              0, 1, seed)
                          .p_value;
                    }});
  checks.push_back({"a7_latin_uniform", "a7.A7.Task2LatinHypercubeDimensionsAreIndependent",
                    k_seed_alpha, true, false, [&s](std::uint64_t seed) {
                      return point_uniformity(s, A7PointSet::latin_hypercube, k_a7_latin_n,
                                              k_a7_latin_dims, 7, 0, k_a7_latin_dims - 1, seed)
                          .p_value;
                    }});
  checks.push_back(
      {"a7_halton_uniform", "a7.A7.Task4ScrambledHaltonPointIsUniform", k_seed_alpha, true, false,
       [&s](std::uint64_t seed) {
         return point_uniformity(s, A7PointSet::halton, k_a7_halton_n, 2, 5, 0, 1, seed).p_value;
       }});
#ifdef MCRT_FAIRNESS_HIDDEN
  for (MeasuredCheck& c : hidden_statistical_checks(s)) checks.push_back(std::move(c));
#endif
  return checks;
}

}  // namespace mcrt::testing::assignment
