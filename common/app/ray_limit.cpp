#include "app/ray_limit.hpp"

#include <string>

#include <fmt/format.h>

#include "app/usage_error.hpp"

namespace mcrt {

namespace {

// A duration in the largest unit that keeps it above 1: "40 s", "3.2 hours", "2e+10 years".
std::string readable_duration(double seconds) {
  constexpr struct {
    double seconds;
    const char* name;
  } units[] = {{365.25 * 86400.0, "years"}, {86400.0, "days"}, {3600.0, "hours"}, {60.0, "min"}};
  for (const auto& unit : units)
    if (seconds >= unit.seconds) return fmt::format("{:.2g} {}", seconds / unit.seconds, unit.name);
  return fmt::format("{:.2g} s", seconds);
}

}  // namespace

void check_furnace_albedo(double albedo) {
  if (albedo >= 1.0)
    throw UsageError(
        "--albedo: give an albedo below 1; at 1 the furnace radiance Le / (1 - a) "
        "is infinite");
}

// One line under 200 characters: what `counted` names is in the chapter's docs, not here.
void check_ray_limit(const RayWork& work, double limit, std::string_view flags, int threads,
                     std::string_view remedy) {
  if (work.predicted_rays <= limit) return;
  const double seconds = work.predicted_rays / (k_estimated_rays_per_second_per_thread * threads);
  throw UsageError(
      fmt::format("{}: about {:.2g} rays (~{} on {} threads), over the limit of {:.2g}; {}", flags,
                  work.predicted_rays, readable_duration(seconds), threads, limit, remedy));
}

}  // namespace mcrt
