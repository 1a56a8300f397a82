#pragma once
// Chapter 07's equal-time pair: uniform and cosine at equal spp (the study's images), cosine
// again at the spp that fits in the uniform image's rays, each against a reference by its
// relative MSE (equal_time.csv). The renders go through the chapter's estimator,
// render_with(scene, camera, pdf, spp, first_sample).

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "io/table.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/relative_error.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

#include "pdf_study.hpp"

namespace mcrt {

// The reference's samples start here: far from every other render's [0, 2 spp), so independent.
inline constexpr std::uint64_t k_reference_first_sample = 1u << 20;

// equal_time.csv: the equal-sample pair, the equal-time cosine image and the reference.
inline Table equal_time_table() {
  return Table({{"image", Column::text},
                {"pdf", Column::text},
                {"spp", Column::integer},
                {"rays", Column::integer},
                {"seconds", Column::real, 6},
                {"relative_mse", Column::real, 9}});  // empty for the reference
}

// Equal time, with rays as the clock: the cosine image gets the samples that fit in the rays
// of the uniform image at spp (paths of the two pdfs escape the scene at different bounces, so
// their rays per sample differ). Rays make the count deterministic; the seconds are measured
// and written beside them.
inline int equal_time_spp(const RenderResult& uniform, const RenderResult& cosine, int spp) {
  const double ratio = static_cast<double>(uniform.rays) / static_cast<double>(cosine.rays);
  return std::clamp(static_cast<int>(std::lround(spp * ratio)), 1, 2 * spp);
}

// The reference: the closed form in the furnace, else the cosine pdf at --reference-spp on
// samples no other render uses.
inline RenderResult reference_image(const auto& render_with, const Scene& scene,
                                    const Camera& camera, const auto& o) {
  if (o.scene.scene == "furnace") {
    const SceneParams& f = o.scene.params;
    RenderResult exact;
    exact.image = Image(o.image.width, o.image.height,
                        Color(furnace_radiance(f.furnace_albedo, f.furnace_emission, o.depth)));
    return exact;
  }
  return render_with(scene, camera, cosine_power_pdf(1), o.reference_spp, k_reference_first_sample);
}

// The comparison's table and the two images it renders.
struct EqualTime {
  Table table = equal_time_table();
  RenderResult cosine_equal_time;
  RenderResult reference;
};

// uniform and cosine at equal spp, cosine at equal time, each against the reference.
inline EqualTime compare_at_equal_time(const auto& render_with, const Study& study,
                                       const Scene& scene, const Camera& camera, const auto& o) {
  const RenderResult& uniform = study.images[0];  // the pdfs start with m = 0, 1
  const RenderResult& cosine = study.images[1];
  const int spp_equal = equal_time_spp(uniform, cosine, o.spp);
  EqualTime result;
  result.cosine_equal_time = render_with(scene, camera, cosine_power_pdf(1), spp_equal, 0);
  result.reference = reference_image(render_with, scene, camera, o);
  const Image& reference = result.reference.image;
  const auto row = [&](const char* image, const char* pdf, int spp, const RenderResult& r) {
    result.table.add_row({image, pdf, spp, r.rays, r.seconds, relative_mse(r.image, reference)});
  };
  row("uniform", "uniform", o.spp, uniform);
  row("cosine", "cosine", o.spp, cosine);
  row("cosine_equal_time", "cosine", spp_equal, result.cosine_equal_time);
  const bool exact = o.scene.scene == "furnace";
  result.table.add_row({"reference", exact ? "closed form" : "cosine", exact ? 0 : o.reference_spp,
                        result.reference.rays, result.reference.seconds, Cell{}});
  return result;
}

}  // namespace mcrt
