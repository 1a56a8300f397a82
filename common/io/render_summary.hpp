#pragma once
/// The summary.json entries every rendering chapter shares: what was rendered (scene and
/// image size) and what it cost (rays, time, speed, non-finite samples).

#include "io/cli.hpp"
#include "io/summary.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

namespace mcrt {

/// "scene", "width", "height".
inline void add_render_setup(Json& summary, const SceneOptions& scene, const ImageOptions& image) {
  summary["scene"] = scene.scene;
  summary["width"] = image.width;
  summary["height"] = image.height;
}

/// "rays", "seconds", "rays_per_second", "non_finite_samples".
inline void add_render_totals(Json& summary, const RenderTotals& totals) {
  summary["rays"] = totals.rays;
  summary["seconds"] = totals.seconds;
  summary["rays_per_second"] = totals.rays_per_second();
  summary["non_finite_samples"] = totals.non_finite_samples;
}

}  // namespace mcrt
