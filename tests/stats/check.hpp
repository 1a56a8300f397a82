#pragma once
// Statistical checks: a named test of an estimator or sampler against its closed form that,
// given a seed, returns a p-value. It fails when p < alpha, so alpha is its designed
// false-failure rate. Every check is run twice over:
//  - by `statistical_checks_test` (label "unit") at the suite's fixed seed, one GoogleTest
//    test per check;
//  - by `calibrate_statistical_checks` (label "calibration") over hundreds of seeds, to
//    measure how often it fails on correct code (it must be close to alpha).
//
// Write a check in tests/checks/TOPIC_checks.cpp:
//
//   MCRT_STATISTICAL_CHECK(disk_area_mean_is_pi, 1e-4) {
//     ... draw with mcrt::Rng(seed, stream) ...
//     return mcrt::testing::z_test_p_value(estimate, k_pi, standard_error);
//   }

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mcrt::testing {

/// The seed every check uses in the default test run.
inline constexpr std::uint64_t k_suite_seed = 20261122;

struct StatisticalCheck {
  std::string name;
  double alpha;                                       ///< designed false-failure rate
  std::function<double(std::uint64_t seed)> p_value;  ///< runs the check, returns its p-value
  /// The design is "at most alpha" (a Sidak combination of correlated statistics, which is
  /// conservative): the calibration then asks only that no rate be above its level and that
  /// the p-values be no smaller than uniform ones, not that they be uniform.
  bool at_most = false;
};

/// Every check linked into the executable, in registration order.
std::vector<StatisticalCheck>& statistical_checks();

struct CheckRegistrar {
  CheckRegistrar(std::string name, double alpha, std::function<double(std::uint64_t)> run,
                 bool at_most = false) {
    statistical_checks().push_back({std::move(name), alpha, std::move(run), at_most});
  }
};

}  // namespace mcrt::testing

#define MCRT_STATISTICAL_CHECK(name, alpha)                                           \
  static double name(std::uint64_t seed);                                             \
  static const ::mcrt::testing::CheckRegistrar name##_registrar{#name, alpha, &name}; \
  static double name([[maybe_unused]] std::uint64_t seed)

/// The same for a check whose false-failure rate is at most alpha by design (StatisticalCheck's
/// at_most).
#define MCRT_STATISTICAL_CHECK_AT_MOST(name, alpha)                                         \
  static double name(std::uint64_t seed);                                                   \
  static const ::mcrt::testing::CheckRegistrar name##_registrar{#name, alpha, &name, true}; \
  static double name([[maybe_unused]] std::uint64_t seed)
