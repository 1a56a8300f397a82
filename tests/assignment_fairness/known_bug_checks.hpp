#pragma once
// Every known bug of tests/assignments/diagnosis_test.cpp as the fairness measurement runs it:
// the check the diagnosis test fails it with, as a single-seed p-value (a statistical check) or
// once (an exact one). Includes the known-wrong variants, so make-assignment withholds it (and
// the program that includes it) from every kit.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "assignments/a1/a1_checks.hpp"
#include "assignments/a2/a2_checks.hpp"
#include "assignments/a3/a3_checks.hpp"
#include "assignments/a4/a4_checks.hpp"
#include "assignments/a5/a5_checks.hpp"
#include "assignments/a6/a6_checks.hpp"
#include "assignments/a7/a7_checks.hpp"
#include "assignments/a7/a7_produce.hpp"
#include "assignments/known_wrong_producers.hpp"
#include "assignments/subject/subject.hpp"
#include "render/mis_known_bugs_a6.hpp"
#include "render/dielectric_known_bugs_a6.hpp"
#include "assignments/a6/a6_dielectric_checks.hpp"
#include "render/recursive_estimator_known_bugs_a3.hpp"
#include "integration/disk_area_known_bugs.hpp"
#include "integration/monte_carlo_known_bugs.hpp"
#include "render/importance_path_tracer_known_bugs.hpp"
#include "render/next_event_estimation_known_bugs.hpp"
#include "render/path_tracer_known_bugs.hpp"
#include "render/russian_roulette_known_bugs.hpp"
#include "sampling/sampling_known_bugs.hpp"
#include "sampling/point_sets_known_bugs_a7.hpp"

namespace mcrt::testing::assignment {

/// A known bug of diagnosis_test.cpp and the check it is expected to fail (or, for the one
/// that only two lights reveal, to pass).
struct MeasuredBug {
  std::string name;
  std::string test;      ///< the diagnosis test that uses it
  std::string check;     ///< the row name of the check it is run through
  bool expected = true;  ///< the diagnosis test expects the check to fail
  bool region = false;
  std::function<double(std::uint64_t)> p_value;  ///< a statistical check: its single-seed p-value
  std::function<bool()> fails;                   ///< an exact check: whether it fails
};

inline std::string diagnosis_test(const char* name) {
  return std::string("assignments.Diagnoses.") + name;
}

inline double cosine_density(const Vec3& w) { return cosine_hemisphere_pdf(w.z); }
inline double uniform_density(const Vec3&) { return uniform_hemisphere_pdf(); }
inline double disk_density(const Vec2&) { return uniform_disk_pdf(); }
inline double cone_density(const Vec3& w) { return uniform_cone_pdf(w.z, k_a2_cone_cos_theta_max); }

/// A wrong sampler (or a right one with a wrong pdf) through a2's chi-square.
template <class Point, class Sampler, class Pdf>
MeasuredBug sampler_bug(const char* name, const char* test, const char* check, Sampler sampler,
                        Pdf pdf, const Binning<Point>& binning) {
  const std::vector<double> probability = bulk_cell_probabilities(each(pdf), binning);
  return {name,
          diagnosis_test(test),
          check,
          true,
          false,
          [=](std::uint64_t seed) {
            return sampler_chi_square(each(sampler), probability, binning, seed).p_value;
          },
          {}};
}

/// A bug caught by an exact check: `result` runs it once.
template <class Result>
MeasuredBug exact_bug(const char* name, const char* test, const char* check, Result result) {
  return {
      name, diagnosis_test(test), check, true, false, {}, [result] { return !result().passed; }};
}

inline std::vector<MeasuredBug> known_bugs() {
  std::vector<MeasuredBug> bugs;
  const auto add = [&](const char* name, const char* test, const char* check, auto p_value,
                       bool region = false, bool expected = true) {
    bugs.push_back({name, diagnosis_test(test), check, expected, region, p_value, {}});
  };
  // a1
  add("a1_disk_without_factor_four", "A1DiskWithoutTheFactorFour", "a1_disk",
      [](std::uint64_t seed) {
        double a = 0.0;
        return disk_p_value(with_disk([](std::uint64_t n, Rng& rng) {
                              return estimate_disk_area(n, rng) / 4.0;
                            }),
                            seed, a);
      });
  add("a1_disk_y_equal_to_x", "A1DiskWithYEqualToX", "a1_disk", [](std::uint64_t seed) {
    double a = 0.0;
    return disk_p_value(with_disk(disk_area_same_coordinate_twice), seed, a);
  });
  add("a1_ball_half_scale", "A1BallHalfScale", "a1_ball", [](std::uint64_t seed) {
    std::vector<double> sums;  // the known bug is a 3-ball's: the diagnosis test checks k = 3
    return balls_p_value(with_ball([](int, std::uint64_t n, Rng& rng) {
                           return ball_volume_half_scale(n, rng);
                         }),
                         {3}, seed, sums);
  });
  add("a1_basic_without_length", "A1MonteCarloWithoutTheLength", "a1_basic_estimator",
      [](std::uint64_t seed) {
        EstimateAndError e;
        return basic_estimator_p_value(with_basic([](const auto& f, const Segment& s,
                                                     std::uint64_t n, Rng& rng) {
                                         MonteCarloEstimate m = monte_carlo(f, s, n, rng);
                                         m.estimate = monte_carlo_without_volume(f, s, n, rng);
                                         return m;
                                       }),
                                       seed, e);
      });
  // a1's answers that are not Monte Carlo (zero spread) and a spread too small and too large
  add("a1_disk_nearest_multiple_of_four_over_n", "A1DiskNearestMultipleOfFourOverN", "a1_disk",
      [](std::uint64_t seed) {
        double a = 0.0;
        return disk_p_value(with_disk(disk_area_nearest_multiple_of_four_over_n), seed, a);
      });
  add("a1_disk_four_times_the_points", "A1DiskFourTimesThePoints", "a1_disk",
      [](std::uint64_t seed) {
        double a = 0.0;
        return disk_p_value(with_disk(disk_area_four_times_the_points), seed, a);
      });
  add("a1_disk_identical_lanes", "A1DiskIdenticalLanes", "a1_disk", [](std::uint64_t seed) {
    double a = 0.0;
    return disk_p_value(with_disk(disk_area_identical_lanes), seed, a);
  });
  add("a1_ball_expected_count", "A1BallExpectedCount", "a1_ball", [](std::uint64_t seed) {
    std::vector<double> sums;
    return balls_p_value(with_ball(ball_volume_expected_count), {2, 3, 5}, seed, sums);
  });
  add("a1_basic_midpoint_rule", "A1MonteCarloMidpointRule", "a1_basic_estimator",
      [](std::uint64_t seed) {
        EstimateAndError e;
        return basic_estimator_p_value(with_basic([](const auto& f, const Segment& s,
                                                     std::uint64_t n, Rng& rng) {
                                         return monte_carlo_midpoint_rule(f, s, n, rng);
                                       }),
                                       seed, e);
      });
  bugs.push_back(exact_bug("a1_trapezoid_full_end_weights", "A1TrapezoidWithFullEndWeights",
                           "a1_trapezoid", [] {
                             return check_trapezoid(
                                 with_rule([](const auto&, const Segment&, std::uint64_t n) {
                                   return trapezoid_with_full_end_weights(Gaussian1D{}, n);
                                 }));
                           }));
  // a2
  bugs.push_back(sampler_bug("a2_uniform_hemisphere_is_cosine", "A2UniformHemisphereThatIsCosine",
                             "a2_uniform_hemisphere", sample_cosine_hemisphere, uniform_density,
                             sampler_hemisphere_binning()));
  bugs.push_back(sampler_bug("a2_uniform_hemisphere_in_angle", "A2UniformHemisphereUniformInAngle",
                             "a2_uniform_hemisphere", hemisphere_uniform_in_angle, uniform_density,
                             sampler_hemisphere_binning()));
  bugs.push_back(sampler_bug("a2_cosine_hemisphere_is_uniform", "A2CosineHemisphereThatIsUniform",
                             "a2_cosine_hemisphere", sample_uniform_hemisphere, cosine_density,
                             sampler_hemisphere_binning()));
  bugs.push_back(sampler_bug("a2_cosine_hemisphere_radius_u", "A2CosineHemisphereWithRadiusU",
                             "a2_cosine_hemisphere", cosine_hemisphere_with_radius_u,
                             cosine_density, sampler_hemisphere_binning()));
  bugs.push_back(sampler_bug("a2_right_sampler_wrong_pdf", "A2RightSamplerWrongPdf",
                             "a2_cosine_hemisphere", sample_cosine_hemisphere, cosine_pdf_times_two,
                             sampler_hemisphere_binning()));
  bugs.push_back(sampler_bug("a2_disk_radius_u", "A2DiskWithRadiusU", "a2_unit_disk",
                             disk_with_radius_u, disk_density, sampler_disk_binning()));
  // a2.5: the cone of k_a2_cone_cos_theta_max
  bugs.push_back(sampler_bug(
      "a2_cone_cos_u_times_max", "A2ConeWithCosUTimesMax", "a2_uniform_cone",
      [](Vec2 u) { return cone_with_cos_u_times_max(u, k_a2_cone_cos_theta_max); }, cone_density,
      sampler_cone_binning()));
  bugs.push_back(sampler_bug(
      "a2_cone_uniform_in_angle", "A2ConeUniformInAngle", "a2_uniform_cone",
      [](Vec2 u) { return cone_uniform_in_angle(u, k_a2_cone_cos_theta_max); }, cone_density,
      sampler_cone_binning()));
  bugs.push_back(
      exact_bug("a2_cone_pdf_without_two_pi", "A2ConePdfWithoutTwoPi", "a2_pdf_integral", [] {
        return check_pdf_integral(each([](const Vec3& w) {
                                    return cone_pdf_without_two_pi(w.z, k_a2_cone_cos_theta_max);
                                  }),
                                  sampler_cone_binning(), "1/(1 - cos)");
      }));
  bugs.push_back(
      exact_bug("a2_hemisphere_pdf_one_over_pi", "A2PdfsOffByTwo", "a2_pdf_integral", [] {
        return check_pdf_integral(each(hemisphere_pdf_one_over_pi), sampler_hemisphere_binning(),
                                  "1/pi");
      }));
  bugs.push_back(exact_bug("a2_cosine_pdf_times_two", "A2PdfsOffByTwo", "a2_pdf_integral", [] {
    return check_pdf_integral(each(cosine_pdf_times_two), sampler_hemisphere_binning(), "2 cos/pi");
  }));
  // a3
  const auto a3_furnace = [&](const char* name, const char* test, auto radiance) {
    add(name, test, "a3_furnace", [radiance](std::uint64_t seed) {
      RunningStats r;
      return recursive_furnace_p_value(a3_producer(radiance), seed, r);
    });
  };
  a3_furnace("a3_one_bounce_late", "A3RecursionOneBounceLate", incident_radiance_one_bounce_late);
  a3_furnace("a3_without_one_over_n", "A3WithoutOneOverN", incident_radiance_without_one_over_n);
  a3_furnace("a3_shared_direction", "A3BranchesSharingOneDirection",
             incident_radiance_one_shared_direction);
  bugs.push_back(
      exact_bug("a3_one_bounce_late_rays", "A3RecursionOneBounceLate", "a3_ray_counts",
                [] { return check_ray_counts(a3_producer(incident_radiance_one_bounce_late)); }));
  bugs.push_back(
      exact_bug("a3_one_bounce_early_rays", "A3RecursionOneBounceEarly", "a3_ray_counts",
                [] { return check_ray_counts(a3_producer(incident_radiance_one_bounce_early)); }));
  // a4
  const auto a4_furnace = [&](const char* name, const char* test, auto radiance) {
    add(name, test, "a4_furnace", [radiance](std::uint64_t seed) {
      double m = 0.0;
      return path_furnace_p_value(furnace_of(radiance), seed, m);
    });
  };
  a4_furnace("a4_missing_cosine", "A4MissingCosine", path_radiance_without_cosine);
  a4_furnace("a4_sphere_pdf", "A4SpherePdf", path_radiance_with_sphere_pdf);
  a4_furnace("a4_cosine_directions_uniform_pdf", "A4CosineDirectionsUniformPdf",
             path_radiance_cosine_directions_uniform_pdf);
  add(
      "a4_cosine_directions_uniform_pdf_regions", "A4CosineDirectionsUniformPdf", "a4_regions",
      [](std::uint64_t seed) {
        int worst = 0;
        double z = 0.0;
        return reference_regions_p_value(sky_of(path_radiance_cosine_directions_uniform_pdf), seed,
                                         worst, z);
      },
      true);
  // a5.1
  const auto roulette = [&](const char* name, const char* test, auto estimator) {
    add(name, test, "a5_roulette_furnace", [estimator](std::uint64_t seed) {
      double mean = 0.0, rays = 0.0;
      return roulette_furnace_p_value(with_roulette(estimator), seed, mean, rays);
    });
  };
  roulette("a5_roulette_without_division", "A5RouletteWithoutDividingByQ",
           roulette_without_division);
  roulette("a5_roulette_before_emission", "A5RouletteBeforeTheEmission", roulette_before_emission);
  roulette("a5_roulette_from_vertex_zero", "A5RouletteFromVertexZero", roulette_from_depth_zero);
  // a5.2
  bugs.push_back(exact_bug("a5_cosine_pdf_without_inv_pi", "A5CosinePdfWithoutOneOverPi",
                           "a5_cosine_furnace_exact", [] {
                             return check_cosine_furnace_is_exact(with_importance(
                                 ignoring_the_pdf(path_radiance_cosine_pdf_without_inv_pi)));
                           }));
  bugs.push_back(exact_bug("a5_cosine_directions_uniform_pdf", "A5CosineDirectionsUniformPdf",
                           "a5_cosine_furnace_exact", [] {
                             return check_cosine_furnace_is_exact(with_importance(
                                 ignoring_the_pdf(path_radiance_cosine_directions_uniform_pdf)));
                           }));
  // a5.3
  bugs.push_back(exact_bug("a5_nee_cut_after_light_sample", "A5NeeCutAfterTheLightSample",
                           "a5_nee_furnace_exact", [] {
                             return check_nee_furnace_is_exact(
                                 with_nee(with_path_end(nee_cut_after_light_sample)));
                           }));
  bugs.push_back(
      exact_bug("a5_nee_without_cos_y", "A5NeeWithoutCosThetaY", "a5_nee_furnace_exact", [] {
        return check_nee_furnace_is_exact(with_nee(with_path_end(nee_without_cos_y)));
      }));
  const auto nee_regions = [&](const char* name, const char* test, auto nee, int parts,
                               bool expected) {
    add(
        name, test, parts == 1 ? "a5_nee_regions" : "a5_nee_two_lights",
        [nee, parts](std::uint64_t seed) {
          int worst = 0;
          double z = 0.0, ratio = 1.0;
          return nee_regions_p_value(with_nee(with_path_end(nee)), seed, worst, z, ratio, parts);
        },
        true, expected);
  };
  nee_regions("a5_nee_emission_twice_regions", "A5NeeEmissionTwice", nee_emission_twice, 1, true);
  nee_regions("a5_nee_without_jacobian_regions", "A5NeeWithoutTheJacobian", nee_without_jacobian, 1,
              true);
  // one light: nothing to see (the diagnosis test expects this check to pass); two: caught
  nee_regions("a5_nee_without_one_over_n_lights_one_light", "A5NeeWithoutOneOverNLights",
              nee_without_one_over_n_lights, 1, false);
  nee_regions("a5_nee_without_one_over_n_lights", "A5NeeWithoutOneOverNLights",
              nee_without_one_over_n_lights, 2, true);
  add("a5_nee_cap_only", "A5NeeCapOnly", "a5_nee_beyond_cap", [](std::uint64_t seed) {
    double r = 1.0;
    return nee_beyond_cap_p_value(with_nee(with_path_end(nee_cap_only)), seed, r);
  });
  const auto nee_exact = [&](const char* name, const char* test, auto nee) {
    bugs.push_back(exact_bug(name, test, "a5_nee_furnace_exact", [nee] {
      return check_nee_furnace_is_exact(with_nee(with_path_end(nee)));
    }));
  };
  nee_exact("a5_nee_emission_twice", "A5NeeEmissionTwice", nee_emission_twice);
  nee_exact("a5_nee_without_jacobian", "A5NeeWithoutTheJacobian", nee_without_jacobian);
  nee_exact("a5_nee_shadow_ray_hits_light", "A5NeeShadowRayHitsTheLight",
            nee_shadow_ray_hits_light);
  // a6.1: a wrong lobe (or the right one against a wrong pdf) through the chi-square at m = 10
  const auto lobe = [&](const char* name, const char* test, auto producer) {
    add(name, test, "a6_phong_lobe", [producer](std::uint64_t seed) {
      const std::vector<double> probability =
          bulk_cell_probabilities(lobe_pdf_of(producer, k_a6_lobe_m), sampler_hemisphere_binning());
      return chi_square_points_test(lobe_samples_at(producer, k_a6_lobe_m, seed), probability,
                                    sampler_hemisphere_binning())
          .p_value;
    });
  };
  lobe("a6_lobe_cosine_to_one_over_m", "A6LobeCosineToOneOverM",
       with_lobe(lobe_cosine_to_one_over_m));
  lobe("a6_lobe_half_the_azimuths", "A6LobeHalfTheAzimuths", with_lobe(lobe_half_the_azimuths));
  lobe("a6_lobe_pdf_with_the_brdfs_normalisation_chi_square", "A6LobePdfWithTheBrdfsNormalisation",
       with_lobe_pdf(lobe_pdf_with_the_brdfs_normalisation));
  bugs.push_back(exact_bug("a6_lobe_pdf_with_the_brdfs_normalisation",
                           "A6LobePdfWithTheBrdfsNormalisation", "a6_lobe_pdf_integral", [] {
                             return check_lobe_pdf_integral(
                                 with_lobe_pdf(lobe_pdf_with_the_brdfs_normalisation));
                           }));
  bugs.push_back(exact_bug("a6_lobe_pdf_round_the_normal", "A6LobePdfRoundTheNormal",
                           "a6_lobe_pdf_round_mirror", [] {
                             return check_lobe_pdf_round_mirror(
                                 with_lobe_pdf(lobe_pdf_round_the_normal));
                           }));
  bugs.push_back(exact_bug("a6_lobe_sine_from_one_minus_cos_squared",
                           "A6LobeSineFromOneMinusCosSquared", "a6_sharp_lobe_digits", [] {
                             return check_sharp_lobe_digits(
                                 with_lobe(lobe_sine_from_one_minus_cos_squared));
                           }));
  // a6.2: exact weights
  const auto heuristic = [&](const char* name, const char* test, auto weight, A6Heuristic h) {
    bugs.push_back(exact_bug(name, test, "a6_heuristic",
                             [weight, h] { return check_heuristic(with_weight(weight), h); }));
  };
  heuristic("a6_power_heuristic_not_squared", "A6PowerHeuristicNotSquared",
            power_heuristic_not_squared, A6Heuristic::power);
  heuristic("a6_heuristic_without_the_guard", "A6HeuristicWithoutTheGuard",
            heuristic_without_the_guard, A6Heuristic::balance);
  heuristic("a6_weights_that_do_not_sum_to_one", "A6WeightsThatDoNotSumToOne",
            weights_that_do_not_sum_to_one, A6Heuristic::power);
  // a6.3: a wrong MIS through the region test of the heuristic its diagnosis test uses
  const auto mis = [&](const char* name, const char* test, auto producer, A6Strategy h,
                       bool expected) {
    add(
        name, test, h == A6Strategy::mis_balance ? "a6_balance_regions" : "a6_power_regions",
        [producer, h](std::uint64_t seed) {
          std::size_t worst = 0;
          double z = 0.0;
          return mis_regions_p_value(mis_region_stats_at(producer, h, seed), worst, z);
        },
        true, expected);
  };
  mis("a6_bsdf_hit_weighted_as_if_by_nee", "A6BsdfHitWeightedAsIfByNee",
      with_mis(mis_bsdf_hit_weighted_as_if_by_nee()), A6Strategy::mis_balance, true);
  mis("a6_bsdf_hit_not_weighted", "A6BsdfHitNotWeighted", with_mis(mis_bsdf_hit_not_weighted()),
      A6Strategy::mis_power, true);
  mis("a6_light_sample_not_weighted", "A6LightSampleNotWeighted",
      with_mis(mis_light_sample_not_weighted()), A6Strategy::mis_power, true);
  mis("a6_light_pdf_per_unit_area", "A6LightPdfPerUnitArea", with_mis(&mis_light_pdf_per_unit_area),
      A6Strategy::mis_balance, true);
  // unbiased: the region test must pass it (its efficiency test catches it: a threshold row)
  mis("a6_light_sampling_passed_off_as_mis_regions", "A6LightSamplingPassedOffAsMis",
      light_sampling_as_mis(), A6Strategy::mis_balance, false);
  // a6.4: a dielectric whose leaving Fresnel uses the indices of entering, through the branch test
  add("a6_dielectric_fresnel_not_inverted", "A6DielectricFresnelNotInvertedWhenLeaving",
      "a6_dielectric_branch", [](std::uint64_t seed) {
        const auto wrong = with_dielectric(&dielectric_fresnel_not_inverted);
        std::string invalid, table;
        return dielectric_branch_p_value(wrong, seed, invalid, table);
      });
  // a7: exact stratification and the recurrence; a point's chi-square (one jitter shared by
  // every stratum fails the rate threshold: a threshold row of measure_assignment_fairness.cpp)
  bugs.push_back(exact_bug("a7_jitter_outside_its_stratum", "A7JitterOutsideItsStratum",
                           "a7_jittered_strata", [] {
                             auto wrong = a7_with<JitterOutsideItsStratum>();
                             return check_jittered_strata(wrong);
                           }));
  add("a7_latin_hypercube_one_permutation", "A7LatinHypercubeWithOnePermutation",
      "a7_latin_uniform", [](std::uint64_t seed) {
        auto wrong = a7_with<JitteredPoints, LatinHypercubeOnePermutation>();
        return point_uniformity(wrong, A7PointSet::latin_hypercube, k_a7_latin_n, k_a7_latin_dims,
                                7, 0, k_a7_latin_dims - 1, seed)
            .p_value;
      });
  add("a7_unscrambled_halton", "A7UnscrambledHaltonClaimedUnbiased", "a7_halton_uniform",
      [](std::uint64_t seed) {
        auto wrong = a7_with<JitteredPoints, LatinHypercubePoints, UnscrambledHalton>();
        return point_uniformity(wrong, A7PointSet::halton, k_a7_halton_n, 2, 5, 0, 1, seed).p_value;
      });
  bugs.push_back(exact_bug("a7_radical_inverse_digits_in_order",
                           "A7RadicalInverseWithItsDigitsInOrder", "a7_radical_inverse", [] {
                             auto wrong = a7_with(&radical_inverse_digits_in_order);
                             return check_radical_inverse(wrong, {2, 3, 5, 7});
                           }));
  return bugs;
}

}  // namespace mcrt::testing::assignment
