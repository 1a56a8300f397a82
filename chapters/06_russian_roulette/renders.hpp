#pragma once
// The scene rendered both ways (depth_cut.png and roulette.png, with their PFMs), and the table
// of the two renders (renders.csv): mean radiance, rays per sample, time.

#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "core/progress.hpp"
#include "geometry/camera.hpp"
#include "io/image_file.hpp"
#include "io/table.hpp"
#include "render/render.hpp"

namespace mcrt {

template <class Estimator>
inline RenderResult render_image(const Camera& camera, const auto& o, const char* label,
                                 Estimator&& estimate) {
  ProgressBar progress(fmt::format("ch06 {}", label), static_cast<std::uint64_t>(o.image.height),
                       o.common.quiet);
  RenderResult result =
      render(camera, {o.spp, 0, o.common.seed, o.common.threads, &progress}, estimate);
  progress.finish();
  write_png(o.common.dir / (std::string(label) + ".png"), result.image);
  write_pfm(o.common.dir / (std::string(label) + ".pfm"), result.image);
  return result;
}

inline Table renders_table() {
  return Table({{"estimator", Column::text},
                {"spp", Column::integer},
                {"mean_radiance", Column::real},
                {"rays", Column::integer},
                {"rays_per_sample", Column::real, 6},
                {"seconds", Column::real, 4},
                {"rays_per_second", Column::real, 4}});
}

inline void add_render_row(Table& table, const char* estimator, const RenderResult& r,
                           const auto& o) {
  const double samples = static_cast<double>(o.image.width) * o.image.height * o.spp;
  table.add_row({estimator, o.spp, mean_radiance(r.image), r.rays,
                 static_cast<double>(r.rays) / samples, r.seconds, r.rays_per_second()});
}

}  // namespace mcrt
