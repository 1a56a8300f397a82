#pragma once
/// The summary.json entries every rendering chapter shares: what was rendered (scene and
/// image size), what it cost (rays, non-finite samples) and, for timings.json, how long it took.

#include "app/cli.hpp"
#include "app/summary.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

namespace mcrt {

/// "scene", "width", "height".
inline void add_render_setup(Json& summary, const SceneOptions& scene, const ImageOptions& image) {
  summary["scene"] = scene.scene;
  summary["width"] = image.width;
  summary["height"] = image.height;
}

/// "rays", "non_finite_samples" (summary.json).
inline void add_render_totals(Json& summary, const RenderTotals& totals) {
  summary["rays"] = totals.rays;
  summary["non_finite_samples"] = totals.non_finite_samples;
}

/// "seconds", "rays_per_second" (timings.json).
inline void add_render_timings(Json& timings, const RenderTotals& totals) {
  timings["seconds"] = totals.seconds;
  timings["rays_per_second"] = totals.rays_per_second();
}

}  // namespace mcrt
