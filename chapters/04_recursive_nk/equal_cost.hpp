#pragma once
// Chapter 04's equal-cost study: at one ray budget per pixel, N = 1 with many camera samples
// against N > 1 with few, each one's error measured from two independent renders.

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "io/table.hpp"
#include "render/image.hpp"
#include "render/recursive_estimator.hpp"
#include "render/recursive_render.hpp"
#include "render/two_render_error.hpp"

#include "plan.hpp"

namespace mcrt {

// 4. Equal cost: the same rays per pixel spent on camera samples (N = 1) or on branches. The
// error of each comes from two independent renders A and B, with no reference image. Each A
// goes to `images` for grid.png's bottom row.
inline Table equal_cost(RecursiveRenderer& render_recursive, const auto& o, const Plan& plan,
                        std::vector<Image>& images) {
  Table table({{"branching", Column::integer},
               {"depth", Column::integer},
               {"spp", Column::integer},
               {"predicted_rays_per_pixel", Column::integer},
               {"rays_per_pixel", Column::real, 9},
               {"seconds", Column::real, 6},
               {"mean_radiance", Column::real, 9},
               {"rms_error", Column::real, 9},
               {"relative_rms_error", Column::real, 9},
               {"rms_error_at_budget", Column::real, 9}});
  const int k = o.equal_cost_depth;
  for (std::size_t i = 0; i < o.branching.size(); ++i) {
    const int n = o.branching[i], spp = plan.equal_cost_spp[i];
    if (spp == 0) continue;  // one sample of this N costs more than the budget
    RenderResult a = render_recursive({n, k}, spp, 0);
    const RenderResult b = render_recursive({n, k}, spp, static_cast<std::uint64_t>(spp));
    const double rays_per_pixel = static_cast<double>(a.rays) / static_cast<double>(plan.pixels);
    const double mean = 0.5 * (mean_radiance(a.image) + mean_radiance(b.image));
    const double rms_error = two_render_rms_error(a.image, b.image);
    // Variance falls as 1/spp, so error scales as 1/sqrt(rays) at a fixed N.
    const double at_budget = rms_error * std::sqrt(rays_per_pixel / o.budget);
    table.add_row({n, k, spp, spp * max_rays_per_sample(n, k), rays_per_pixel,
                   a.seconds + b.seconds, mean, rms_error, mean > 0.0 ? rms_error / mean : 0.0,
                   at_budget});
    images.push_back(std::move(a.image));
  }
  return table;
}

}  // namespace mcrt
