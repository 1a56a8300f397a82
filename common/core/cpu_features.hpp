#pragma once
/// What the processor can do, asked once: the fast engines choose their path from this.

namespace mcrt {

/// Whether the processor runs AVX2 instructions (always false off x86-64).
inline bool cpu_has_avx2() {
#if defined(__x86_64__)
  // __builtin_cpu_init is needed when this runs before main, from a static initialiser.
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return has;
#else
  return false;
#endif
}

/// Whether the processor (and the operating system, which must save the wider registers) runs
/// the AVX-512 subsets F, BW, VL and DQ: 32-bit words sixteen to a register, bytes shuffled in
/// them, 64-bit multiplies (always false off x86-64).
inline bool cpu_has_avx512() {
#if defined(__x86_64__)
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
           __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
  }();
  return has;
#else
  return false;
#endif
}

}  // namespace mcrt
