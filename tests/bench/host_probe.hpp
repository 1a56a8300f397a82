#pragma once
// What the host's two cores share, for reading the two-thread figures beside them. A virtual
// machine's two vCPUs may be two hardware threads of one physical core (SMT siblings), or
// share parts of a core with another tenant, and that changes with the hypervisor's placement.
// Three small loops, each run by one thread and by two, tell which kind of work two threads
// run at twice the rate of one on this host:
//  - one dependent chain of multiply-adds waits on each result (latency-bound): two threads
//    run it 2x one thread wherever they are;
//  - twelve independent chains keep both FMA units of a core busy (throughput-bound);
//  - stores and loads of twelve counters in the level-1 cache (the memory pipeline).
// Code whose scaling matches the third's, not the first two's, is held back by what the host's
// cores share, not by its threading.

#include <cstdint>

#include "core/cpu_features.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace mcrt::bench {

/// `steps` increments of each of twelve counters, each a load and a store in the level-1
/// cache (volatile: the compiler keeps every one).
inline void increment_counters(volatile std::uint64_t (&counters)[12], std::uint64_t steps) {
  for (std::uint64_t i = 0; i < steps; ++i)
    for (volatile std::uint64_t& counter : counters) counter = counter + 1;
}

#if defined(__x86_64__)
/// `steps` multiply-adds x <- x m + a in each of `Chains` independent chains of four doubles;
/// returns their sum, so that nothing can be left out. Needs AVX2 and FMA (ask first).
template <int Chains>
__attribute__((target("avx2,fma"))) double multiply_add_chains(std::uint64_t steps) {
  __m256d x[Chains];
  for (int c = 0; c < Chains; ++c) x[c] = _mm256_set1_pd(1.0 + 1e-3 * c);
  const __m256d m = _mm256_set1_pd(0.9999999);  // |m| < 1: x stays near a / (1 - m)
  const __m256d a = _mm256_set1_pd(1e-7);
  for (std::uint64_t i = 0; i < steps; ++i)
    for (int c = 0; c < Chains; ++c) x[c] = _mm256_fmadd_pd(x[c], m, a);
  __m256d sum = _mm256_setzero_pd();
  for (int c = 0; c < Chains; ++c) sum = _mm256_add_pd(sum, x[c]);
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, sum);
  return lanes[0] + lanes[1] + lanes[2] + lanes[3];
}

/// Whether the processor runs the probe's AVX2 and FMA instructions.
inline bool cpu_has_avx2_and_fma() { return cpu_has_avx2() && __builtin_cpu_supports("fma"); }
#endif

}  // namespace mcrt::bench
