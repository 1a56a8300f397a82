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

}  // namespace mcrt
