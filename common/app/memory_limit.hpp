#pragma once
/// Memory is work too: a chapter predicts from its flags the peak memory of a run and refuses,
/// before allocating, a run over what the machine can give it (exit 2, the estimate and the
/// flags to lower). An allocation that fails anyway ends the run with one line naming the cause
/// (exit 1), never a bare std::bad_alloc.

#include <string_view>

namespace mcrt {

/// Bytes of one image in memory (render/image.hpp: three doubles per pixel).
inline constexpr double k_image_bytes_per_pixel = 24.0;

/// What a run would hold at its peak: an upper bound in bytes and, in words, what it counts.
struct MemoryUse {
  double bytes = 0.0;
  std::string_view counted;  ///< e.g. "about 9 images of width x height"
};

/// A renderer's peak: `images` images of `pixels` pixels held at once, beside a fixed base (the
/// program, its libraries, encoders' buffers: 64 MB) and a stack of 8 MiB per thread (the
/// address space ulimit -v counts). `images` is an upper bound a chapter counts from its code
/// and checks against a measured peak (its comment says which).
inline MemoryUse images_in_memory(double pixels, double images, int threads,
                                  std::string_view counted) {
  return {64e6 + threads * 8.0 * 1024 * 1024 + images * pixels * k_image_bytes_per_pixel,
          counted};
}

/// The memory this process may still take: the smallest of the machine's available memory
/// (MemAvailable in /proc/meminfo), what a container's limit leaves (cgroup v2 memory.max
/// less memory.current), and what `ulimit -v` (RLIMIT_AS) and `ulimit -d`
/// (RLIMIT_DATA) leave beside what it holds already. Infinity when none is known.
double available_memory_bytes();

/// Throws UsageError (exit 2) if use.bytes exceeds available_memory_bytes(), with one line
/// naming `flags`, the estimate, what it counts, what is available and `remedy`. Also makes
/// a failed allocation throw an std::bad_alloc whose message names the cause and the remedy.
void check_memory_limit(const MemoryUse& use, std::string_view flags, std::string_view remedy);

}  // namespace mcrt
