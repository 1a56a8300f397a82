// The rates of chapter 09's studies, as statistical checks: for each point set on the disk
// and on the smooth bump, the slope of log rmse against log N (R = 32 randomisations at
// N = 16 ... 4096) within its band (point_set_rates.hpp): |slope - predicted| at most the
// band's allowance plus noise. The p-value is that of the excess beyond the allowance as a
// normal z-score, so each check fails with probability at most alpha = 1e-4 (13 checks: at
// most 1.3e-3 for the family) when the allowance covers the systematic part.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/math.hpp"
#include "integration/point_set_rates.hpp"
#include "sampling/point_sets.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"

namespace {

using mcrt::testing::measure_rate;
using mcrt::testing::rate_band;

constexpr int k_trials = 32;

std::vector<std::uint32_t> powers_of_two() {
  std::vector<std::uint32_t> sizes;
  for (std::uint32_t n = 16; n <= 4096; n *= 2) sizes.push_back(n);
  return sizes;
}

// round(2^(m + 1/2)) made odd, as chapter 09's odd sizes.
std::vector<std::uint32_t> odd_sizes() {
  std::vector<std::uint32_t> sizes;
  for (std::uint32_t n = 16; 2 * n <= 4096; n *= 2)
    sizes.push_back(static_cast<std::uint32_t>(std::lround(n * std::sqrt(2.0))) | 1u);
  return sizes;
}

template <class MakePoints>
double rate_p_value(const std::string& study, const std::string& sampler, MakePoints make,
                    std::uint64_t seed, const std::vector<std::uint32_t>& sizes = powers_of_two()) {
  const bool disk = study == "disk";
  const auto rate =
      disk ? measure_rate(make, mcrt::testing::disk_times_area, mcrt::k_pi, sizes, k_trials, seed)
           : measure_rate(make, mcrt::testing::smooth_bump, mcrt::testing::smooth_bump_integral(),
                          sizes, k_trials, seed);
  const double z =
      mcrt::testing::excess_over_allowance(rate.slope, rate.noise_sd, rate_band(study, sampler));
  return mcrt::testing::z_test_p_value(z, 0.0, 1.0);
}

auto independent = [](std::uint32_t n, std::uint64_t k) { return mcrt::IndependentPoints{n, k}; };
auto jittered = [](std::uint32_t n, std::uint64_t k) { return mcrt::JitteredPoints{n, 2, k}; };
auto latin = [](std::uint32_t n, std::uint64_t k) { return mcrt::LatinHypercubePoints{n, k}; };
auto sobol_xor = [](std::uint32_t n, std::uint64_t k) {
  return mcrt::SobolPoints{n, k, mcrt::SobolScramble::xor_shift};
};
auto sobol_owen = [](std::uint32_t n, std::uint64_t k) {
  return mcrt::SobolPoints{n, k, mcrt::SobolScramble::owen};
};
auto halton = [](std::uint32_t n, std::uint64_t k) { return mcrt::HaltonPoints{n, k}; };

MCRT_STATISTICAL_CHECK_AT_MOST(disk_rate_independent, 1e-4) {
  return rate_p_value("disk", "independent", independent, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(disk_rate_jittered, 1e-4) {
  return rate_p_value("disk", "jittered", jittered, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(disk_rate_latin_hypercube, 1e-4) {
  return rate_p_value("disk", "latin_hypercube", latin, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(disk_rate_sobol_xor, 1e-4) {
  return rate_p_value("disk", "sobol_xor", sobol_xor, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(disk_rate_sobol_owen, 1e-4) {
  return rate_p_value("disk", "sobol_owen", sobol_owen, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(disk_rate_halton, 1e-4) {
  return rate_p_value("disk", "halton", halton, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_independent, 1e-4) {
  return rate_p_value("smooth", "independent", independent, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_jittered, 1e-4) {
  return rate_p_value("smooth", "jittered", jittered, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_latin_hypercube, 1e-4) {
  return rate_p_value("smooth", "latin_hypercube", latin, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_sobol_xor, 1e-4) {
  return rate_p_value("smooth", "sobol_xor", sobol_xor, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_sobol_owen, 1e-4) {
  return rate_p_value("smooth", "sobol_owen", sobol_owen, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_halton, 1e-4) {
  return rate_p_value("smooth", "halton", halton, seed);
}
MCRT_STATISTICAL_CHECK_AT_MOST(smooth_rate_sobol_owen_odd_n, 1e-4) {
  return rate_p_value("smooth", "sobol_owen_odd_n", sobol_owen, seed, odd_sizes());
}

}  // namespace
