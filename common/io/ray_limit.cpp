#include "io/ray_limit.hpp"

#include <fmt/format.h>

#include "io/cli.hpp"

namespace mcrt {

void check_ray_limit(const RayWork& work, double limit, std::string_view flags, int threads,
                     std::string_view remedy) {
  if (work.predicted_rays <= limit) return;
  const double seconds = work.predicted_rays / (k_estimated_rays_per_second_per_thread * threads);
  throw UsageError(fmt::format(
      "{}: this run would trace up to {:.3g} rays ({}), about {:.3g} s at an estimated {:.3g} "
      "rays/s per thread on {} threads, above the limit of {:.3g}; {}",
      flags, work.predicted_rays, work.counted, seconds, k_estimated_rays_per_second_per_thread,
      threads, limit, remedy));
}

}  // namespace mcrt
