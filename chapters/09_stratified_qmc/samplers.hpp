#pragma once
// Chapter 09's samplers: the point sets of common/sampling/point_sets.hpp by name, each
// randomised by a key so that every point alone is uniform on [0,1)^k (the estimates stay
// unbiased), and the slope each study predicts for its rms error against N.

#include <cstdint>
#include <string>

#include "sampling/point_sets.hpp"

namespace mcrt::ch09 {

enum class Sampler { independent, jittered, latin_hypercube, sobol_xor, sobol_owen, halton };

inline constexpr Sampler k_samplers[] = {Sampler::independent,     Sampler::jittered,
                                         Sampler::latin_hypercube, Sampler::sobol_xor,
                                         Sampler::sobol_owen,      Sampler::halton};

inline std::string name_of(Sampler sampler) {
  const char* names[] = {"independent", "jittered",   "latin_hypercube",
                         "sobol_xor",   "sobol_owen", "halton"};
  return names[static_cast<int>(sampler)];
}

// Calls visit(points) with the sampler's set of n points in `dims` dimensions for `key`, as
// its own type, so that the estimator's loop is compiled (and inlined) for each set.
template <class Visit>
auto with_points(Sampler sampler, std::uint32_t n, unsigned dims, std::uint64_t key,
                 Visit&& visit) {
  switch (sampler) {
    case Sampler::independent: return visit(IndependentPoints{n, key});
    case Sampler::jittered: return visit(JitteredPoints{n, dims, key});
    case Sampler::latin_hypercube: return visit(LatinHypercubePoints{n, key});
    case Sampler::sobol_xor: return visit(SobolPoints{n, key, SobolScramble::xor_shift});
    case Sampler::sobol_owen: return visit(SobolPoints{n, key, SobolScramble::owen});
    case Sampler::halton:
    default: return visit(HaltonPoints{n, key});
  }
}

// The disk (an indicator with a curved edge, 2D). Independent points and Latin hypercube
// (which integrates away only the additive part, and the indicator has none worth the
// name): Var = sigma^2/N, slope -1/2. A grid of N cells of side h = N^-1/2 has about
// 2 pi / h = O(N^1/2) cells on the edge, each of variance at most 1/4 (scaled by 1/N^2):
// Var = O(N^-3/2), slope -3/4, for jittered points and for every set that stratifies the
// square as finely (nets, scrambled Halton).
inline double disk_predicted_slope(Sampler sampler) {
  return sampler == Sampler::independent || sampler == Sampler::latin_hypercube ? -0.5 : -0.75;
}

// A smooth integrand (2D). Independent and Latin hypercube (the interaction part remains):
// -1/2. A jittered cell of side h varies by O(h) about its mean: Var = N (h^2 / N^2) = N^-2,
// slope -1; so do a random digital shift of a net and scrambled Halton (up to logs). Owen's
// nested scramble at N = 2^m: Var = O(N^-3 log N), slope about -3/2 (Owen 1997); at other N
// the incomplete last block adds an error O(1/N): slope -1.
inline double smooth_predicted_slope(Sampler sampler, bool power_of_two) {
  switch (sampler) {
    case Sampler::independent:
    case Sampler::latin_hypercube: return -0.5;
    case Sampler::sobol_owen: return power_of_two ? -1.5 : -1.0;
    default: return -1.0;
  }
}

}  // namespace mcrt::ch09
