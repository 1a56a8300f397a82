#pragma once
// What a check may ask of the code under test, shared by LocalSubject (the student's functions
// called in-process), RemoteSubject (the same requests sent to the subject program) and the
// subject program's dispatcher. No student header is included here: the checker uses this.

#include <cstdint>
#include <vector>

#include "core/math.hpp"

namespace mcrt::testing::assignment {

/// a2's four samplers (each with its pdf).
enum class SamplerKind { uniform_hemisphere, cosine_hemisphere, uniform_sphere, unit_disk };

/// Request names, as they travel in frames.
inline constexpr const char* k_request_a2_samples = "a2_samples";
inline constexpr const char* k_request_a2_pdf = "a2_pdf";
inline constexpr const char* k_request_a4_furnace = "a4_furnace";
inline constexpr const char* k_request_a4_sky = "a4_sky";
inline constexpr const char* k_request_a4_single = "a4_single";

/// One path's channel-mean radiance and its rays (a4's single path).
struct PathSample {
  double radiance = 0.0;
  std::uint64_t rays = 0;
};

/// A seed, block or count sent as a double: exact below 2^53, which every request stays under.
inline double as_number(std::uint64_t x) { return static_cast<double>(x); }

/// Points travel as x, y, z triples (a disk point with z = 0).
inline std::vector<double> flatten(const std::vector<Vec3>& points) {
  std::vector<double> out;
  out.reserve(points.size() * 3);
  for (const Vec3& p : points) out.insert(out.end(), {p.x, p.y, p.z});
  return out;
}

inline std::vector<Vec3> unflatten3(const double* values, std::size_t count) {
  std::vector<Vec3> out;
  out.reserve(count / 3);
  for (std::size_t i = 0; i + 2 < count; i += 3) out.emplace_back(values[i], values[i + 1], values[i + 2]);
  return out;
}

}  // namespace mcrt::testing::assignment
