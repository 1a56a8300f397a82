#pragma once
/// Memory is work too: a chapter predicts its peak memory from its flags and refuses, before
/// allocating, a run over what the machine can give (exit 2). An allocation that fails anyway
/// ends the run with one line naming the cause (exit 1), never a bare std::bad_alloc.

#include <filesystem>
#include <string_view>

namespace mcrt {

/// Bytes of one image in memory (render/image.hpp: three doubles per pixel).
inline constexpr double k_image_bytes_per_pixel = 24.0;

/// A run's peak: an upper bound in bytes and, in words, what it counts.
struct MemoryUse {
  double bytes = 0.0;
  std::string_view counted;  ///< e.g. "about 9 images of width x height"
};

/// A renderer's peak: `images` images of `pixels` pixels (an upper bound the chapter counts
/// from its code), a base of 64 MB (program, libraries, encoders) and 8 MiB of stack per thread.
inline MemoryUse images_in_memory(double pixels, double images, int threads,
                                  std::string_view counted) {
  return {64e6 + threads * 8.0 * 1024 * 1024 + images * pixels * k_image_bytes_per_pixel, counted};
}

/// What a container's memory limit under `root` leaves: cgroup v2 (memory.max less
/// memory.current) or v1 (memory/memory.limit_in_bytes less memory/memory.usage_in_bytes);
/// infinity without one.
double left_in_cgroup(const std::filesystem::path& root = "/sys/fs/cgroup");

/// The memory this process may still take: the least of MemAvailable (/proc/meminfo),
/// left_in_cgroup(), and what `ulimit -v` and `ulimit -d` leave. Infinity when none is known.
double available_memory_bytes();

/// Throws UsageError (exit 2) if use.bytes exceeds available_memory_bytes(), one line naming
/// `flags`, the estimate, what it counts, what is available and `remedy`. Also makes a failed
/// allocation throw a std::bad_alloc whose message names the cause and the remedy.
void check_memory_limit(const MemoryUse& use, std::string_view flags, std::string_view remedy);

}  // namespace mcrt
