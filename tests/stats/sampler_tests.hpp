#pragma once
// The chi-square tests every sampler of common/sampling/ is held to. The statistical checks
// (tests/sampling/sampling_checks.cpp) run them on the real samplers and the known-bug tests
// (tests/stats/known_bugs_test.cpp) on deliberately wrong ones: the same test, the same seed.
//
// Each draws 1e5 points and bins them into about 230 equal-measure cells, ~430 expected per
// cell: enough for the chi-square approximation everywhere but the cosine sampler's grazing
// row, which pooling covers. Its false-failure rate is alpha = 1e-4.

#include <cstdint>
#include <string>

#include "stats/binning.hpp"
#include "stats/chi_square.hpp"

namespace mcrt::testing {

/// Each sampler's test draws from its own generator stream (with the suite's seed), so the
/// tests are independent of each other: the disk's (r^2, phi) and the hemisphere's
/// (phi, cos theta) cells cut the square of uniforms u alike, and on one stream the two tests
/// would see the same counts.
inline constexpr std::uint64_t k_square_stream = 1;
inline constexpr std::uint64_t k_disk_stream = 2;
inline constexpr std::uint64_t k_uniform_hemisphere_stream = 3;
inline constexpr std::uint64_t k_cosine_hemisphere_stream = 4;
inline constexpr std::uint64_t k_uniform_sphere_stream = 5;

/// Designed false-failure rate of one sampler test.
inline constexpr double k_sampler_alpha = 1e-4;
/// Points drawn per sampler test.
inline constexpr std::uint64_t k_sampler_samples = 100000;

/// 15 x 15 cells on [-1,1]^2.
inline Binning<Vec2> sampler_square_binning() { return square_binning(15); }
/// 11 rings (equal r^2 steps) by 21 sectors.
inline Binning<Vec2> sampler_disk_binning() { return disk_binning(11, 21); }
/// 21 phi by 11 cos(theta) cells: odd counts (see hemisphere_binning).
inline Binning<Vec3> sampler_hemisphere_binning() { return hemisphere_binning(21, 11); }

/// Chi-square p-value of a sampler Vec2(Vec2 u) on the square [-1,1]^2 against its pdf
/// double(Vec2 x), u drawn from Rng(seed, stream); on failure a report named `name` is written.
template <class Sampler, class Pdf>
double square_sampler_p_value(const Sampler& sample, const Pdf& pdf, std::uint64_t seed,
                              std::uint64_t stream, const std::string& name) {
  return chi_square_sampler_p_value(sample, pdf, sampler_square_binning(), seed,
                                    {name, k_sampler_samples, stream, k_sampler_alpha});
}

/// The same for a sampler of the unit disk.
template <class Sampler, class Pdf>
double disk_sampler_p_value(const Sampler& sample, const Pdf& pdf, std::uint64_t seed,
                            std::uint64_t stream, const std::string& name) {
  return chi_square_sampler_p_value(sample, pdf, sampler_disk_binning(), seed,
                                    {name, k_sampler_samples, stream, k_sampler_alpha});
}

/// The same for a sampler of directions Vec3(Vec2 u) on the hemisphere around +z, against
/// its pdf double(Vec3 w) per steradian.
template <class Sampler, class Pdf>
double hemisphere_sampler_p_value(const Sampler& sample, const Pdf& pdf, std::uint64_t seed,
                                  std::uint64_t stream, const std::string& name) {
  return chi_square_sampler_p_value(sample, pdf, sampler_hemisphere_binning(), seed,
                                    {name, k_sampler_samples, stream, k_sampler_alpha});
}

/// The same for a sampler of directions on the whole sphere, 21 phi by 21 z cells.
template <class Sampler, class Pdf>
double sphere_sampler_p_value(const Sampler& sample, const Pdf& pdf, std::uint64_t seed,
                              std::uint64_t stream, const std::string& name) {
  return chi_square_sampler_p_value(sample, pdf, sphere_binning(21, 21), seed,
                                    {name, k_sampler_samples, stream, k_sampler_alpha});
}

}  // namespace mcrt::testing
