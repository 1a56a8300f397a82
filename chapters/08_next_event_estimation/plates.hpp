#pragma once
// Veach's plates: where MIS earns its place. Four glossy plates (rough to sharp) reflect four
// lights of equal power (small and bright to large and dim), rendered by light sampling only,
// BSDF sampling only and MIS (balance, power), at equal rays: every strategy traces 3 rays per
// sample that meets a plate (render/glossy_direct.hpp says how), and all run the same spp, so
// the ray counts in plates.csv are equal. Each is compared with a reference (MIS power at
// k_plates_reference_factor times the spp, from sample indices none of the four uses) in 16
// pixel boxes, one round each light's highlight in each plate (render/veach_plates.hpp), seen
// through the figure's camera (make_veach_plates_figure).
//
// Expected (Veach, fig. 9.2): light sampling wins on rough plates with small lights, BSDF
// sampling on sharp plates with large lights, MIS is close to the better of the two everywhere.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "geometry/camera.hpp"
#include "io/image_file.hpp"
#include "io/contact_sheet.hpp"
#include "io/table.hpp"
#include "io/text.hpp"
#include "render/glossy_direct.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/veach_plates.hpp"

namespace mcrt {

struct GlossyStrategyInfo {
  GlossyStrategy strategy;
  std::string_view name;   // plates.csv
  std::string_view label;  // plates.png
};
inline constexpr std::array<GlossyStrategyInfo, 4> k_glossy_strategies{{
    {GlossyStrategy::light, "light", "light sampling"},
    {GlossyStrategy::bsdf, "bsdf", "BSDF sampling"},
    {GlossyStrategy::mis_balance, "mis_balance", "MIS balance"},
    {GlossyStrategy::mis_power, "mis_power", "MIS power"},
}};

// The reference's spp per spp of the four. Its own variance adds Var R = Var(MIS power) / 16
// to every cell's relMSE (E[(A - R)^2] = Var A + Var R for independent A and R): 6 % of MIS
// power's, about 12 % of the best strategy's where MIS power is twice the best (a cell's own
// relMSE moves by tens of percent between seeds). It is the same term for the four strategies
// of a cell (one reference), so it narrows their ratios but does not reorder them. 16, not 32: at the figure's 240 x 180 the reference is most of the
// study's rays, and the chapter's run time may not grow by more than a few percent.
inline constexpr int k_plates_reference_factor = 16;
// The plates render at 1.5 times --width and --height (240 x 180 by default) and show 2x:
// panels 480 pixels wide, each plate 30-40 rows tall before the blow-up.
inline constexpr double k_plates_image_scale = 1.5;
inline int plates_image_size(int flag) {
  return std::max(1, static_cast<int>(std::lround(k_plates_image_scale * flag)));
}
// Rays per pixel sample at most: the camera ray and two more (the rule above).
inline constexpr double k_plates_rays_per_sample = 3.0;

// Rays the study may trace: the four renders and the reference.
inline double plates_predicted_rays(int width, int height, int spp) {
  return static_cast<double>(plates_image_size(width)) * plates_image_size(height) * spp *
         k_plates_rays_per_sample *
         (static_cast<double>(k_glossy_strategies.size()) + k_plates_reference_factor);
}

struct PlatesStudy {
  Table table;
  std::vector<Image> images;  // one per strategy, then the reference
  RenderTotals total;
};

inline Table plates_table() {
  return Table({{"plate", Column::integer},
                {"exponent", Column::real, 6},
                {"light", Column::integer},
                {"light_radius", Column::real, 6},
                {"x0", Column::integer},
                {"x1", Column::integer},
                {"y0", Column::integer},
                {"y1", Column::integer},
                {"strategy", Column::text},
                {"rays_per_pixel", Column::real, 6},
                {"rel_mse", Column::real, 6},
                {"rel_mse_vs_best", Column::real, 6},
                {"winner", Column::text}});
}

// The four renders at `spp`, the reference, and the table: per plate x light region, each
// strategy's relMSE, its ratio to the cell's best, and the cell's winner. Every sample draws
// from the stream of its pixel and index (render/render.hpp), so all of it is the same for a
// seed whatever `threads`.
inline PlatesStudy run_plates_study(int flag_width, int flag_height, int spp, std::uint64_t seed,
                                    int threads) {
  const int width = plates_image_size(flag_width), height = plates_image_size(flag_height);
  const VeachPlates scene = make_veach_plates_figure();
  const Camera camera(scene.camera, width, height);
  PlatesStudy study{plates_table(), {}, {}};
  std::vector<double> rays_per_pixel;
  const double pixels = static_cast<double>(width) * height;
  for (const GlossyStrategyInfo& s : k_glossy_strategies) {
    const RenderResult r =
        render(camera, {spp, 0, seed, threads, nullptr},
               [&](const Ray& ray, Rng& rng, RayCount& count) {
                 return estimate_plates_radiance(scene, ray, s.strategy, rng, count);
               });
    study.total.add(r);
    study.images.push_back(r.image);
    rays_per_pixel.push_back(static_cast<double>(r.rays) / pixels);
  }
  const RenderResult reference =
      render(camera,
             {spp * k_plates_reference_factor, static_cast<std::uint64_t>(spp), seed, threads,
              nullptr},
             [&](const Ray& ray, Rng& rng, RayCount& count) {
               return estimate_plates_radiance(scene, ray, GlossyStrategy::mis_power, rng, count);
             });
  study.total.add(reference);
  study.images.push_back(reference.image);

  for (const PlateRegion& region : plate_regions(scene, width, height)) {
    std::vector<double> rel_mse;
    std::size_t best = 0;
    for (std::size_t i = 0; i < k_glossy_strategies.size(); ++i) {
      rel_mse.push_back(region_relative_mse(study.images[i], reference.image, region));
      if (rel_mse[i] < rel_mse[best]) best = i;
    }
    for (std::size_t i = 0; i < k_glossy_strategies.size(); ++i)
      study.table.add_row({static_cast<int>(region.plate), k_plate_exponents[region.plate],
                           static_cast<int>(region.light), k_plate_light_radii[region.light],
                           region.x0, region.x1, region.y0, region.y1,
                           std::string(k_glossy_strategies[i].name), rays_per_pixel[i], rel_mse[i],
                           rel_mse[best] > 0.0 ? rel_mse[i] / rel_mse[best] : 1.0,
                           std::string(k_glossy_strategies[best].name)});
  }
  return study;
}

// The console's view of plates.csv: per plate (rows) and light (columns) the winner, and MIS
// power's relMSE over the winner's.
inline std::string plates_console(const PlatesStudy& study) {
  std::string out =
      "  Veach's plates, winner per plate (rows, rough to sharp) and light (columns, "
      "small to large), [MIS power / best]:\n";
  for (std::size_t i = 0; i < study.table.size(); ++i) {
    if (study.table.at(i, "strategy").json() != "mis_power") continue;
    const int light = static_cast<int>(study.table.at(i, "light").json().get<double>());
    if (light == 0)
      out += fmt::format("    m = {:<6}", study.table.at(i, "exponent").json().get<double>());
    out += fmt::format("  {:>11} [{:4.2f}]", study.table.at(i, "winner").json().get<std::string>(),
                       study.table.at(i, "rel_mse_vs_best").json().get<double>());
    if (light + 1 == static_cast<int>(k_plate_light_radii.size())) out += "\n";
  }
  return out;
}

// The relMSE of one panel over the 16 boxes together (pixel-weighted), and per plate over its
// four boxes (they tile the plate's trimmed rows, so their union is one box).
struct PanelErrors {
  double all = 0.0;
  std::array<double, 4> plate{};
};
inline PanelErrors panel_errors(const Image& image, const Image& reference,
                                const std::vector<PlateRegion>& regions) {
  PanelErrors e;
  double pixels = 0.0;
  for (const PlateRegion& r : regions) {
    e.all += region_relative_mse(image, reference, r) * r.pixel_count();
    pixels += r.pixel_count();
  }
  e.all = pixels > 0.0 ? e.all / pixels : 0.0;
  for (std::size_t k = 0; k < e.plate.size(); ++k) {
    PlateRegion whole = regions[4 * k];
    whole.x1 = regions[4 * k + 3].x1;
    e.plate[k] = region_relative_mse(image, reference, whole);
  }
  return e;
}

// The figure's tone curve, y = k L / (1 + k L) per channel: the plates' radiance spans 0.05
// (the rough plate) to 20 (the sharp plate's small lights), which no one exposure shows. With
// k = 4 the rough plate's glow (L ~ 0.05-0.1) is grey, the next plate's (L ~ 0.2) light grey,
// the sharp plates' highlights (L > 1) near white, and a firefly never clips to a flat blob.
// Display only: the relMSE of the table and the labels are those of the rendered values.
inline constexpr double k_plates_exposure = 4.0;

// plates.png: the four strategies and the reference (3 per row), each blown up 2x (a noisy
// highlight a few pixels wide stays visible) under a label with its relMSE over the 16 boxes,
// and, right of each plate, its own relMSE (green on the plate's winner). Then plates.csv.
inline void write_plates(const std::filesystem::path& dir, const PlatesStudy& study, int spp) {
  constexpr int k_factor = 2, k_text = 2;
  const int width = study.images.back().width, height = study.images.back().height;
  const std::vector<PlateRegion> regions = plate_regions(make_veach_plates_figure(), width, height);
  const Image& reference = study.images.back();
  std::vector<PanelErrors> errors;
  for (std::size_t i = 0; i < k_glossy_strategies.size(); ++i)
    errors.push_back(panel_errors(study.images[i], reference, regions));
  const int margin = text_width("0.00000", k_text) + 8;  // the column of per-plate numbers
  std::vector<Image> panels;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < study.images.size(); ++i) {
    const Image blown_up = upscale_nearest(study.images[i], k_factor);
    Image panel(blown_up.width + margin, blown_up.height);
    for (int y = 0; y < blown_up.height; ++y)
      for (int x = 0; x < blown_up.width; ++x) {
        const Color l = k_plates_exposure * blown_up.at(x, y);
        panel.at(x, y) = l / (Color(1.0) + l);
      }
    if (i < errors.size()) {
      labels.push_back(
          fmt::format("{}: relMSE {:.3g}", k_glossy_strategies[i].label, errors[i].all));
      for (std::size_t k = 0; k < errors[i].plate.size(); ++k) {
        bool best = true;
        for (const PanelErrors& other : errors) best = best && errors[i].plate[k] <= other.plate[k];
        const PlateRegion& r = regions[4 * k];
        const int y = k_factor * (r.y0 + r.y1) / 2 - text_height(k_text) / 2;
        draw_text(panel, blown_up.width + 4, y, fmt::format("{:.3g}", errors[i].plate[k]),
                  best ? Color(0.05, 1.0, 0.05) : Color(1.0), k_text);
      }
    } else {
      labels.push_back(fmt::format("reference ({} spp)", spp * k_plates_reference_factor));
    }
    panels.push_back(std::move(panel));
  }
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < panels.size(); ++i) cells.push_back({&panels[i], labels[i]});
  SheetLayout layout;
  layout.columns = 3;
  layout.title = fmt::format(
      "Veach's plates at equal rays ({} spp, 3 rays a sample), plates rough "
      "(bottom) to sharp, lights small (left) to large; on each plate its "
      "relMSE on its right, green for the best",
      spp);
  write_png(dir / "plates.png", make_contact_sheet(cells, layout));
  write_csv(dir / "plates.csv", study.table);
}

}  // namespace mcrt
