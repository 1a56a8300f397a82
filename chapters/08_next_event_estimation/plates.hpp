#pragma once
// Veach's plates: where MIS earns its place. Four glossy plates (rough to sharp) reflect four
// lights of equal power (small and bright to large and dim), rendered by light sampling only,
// BSDF sampling only and MIS (balance, power), at equal rays: every strategy traces 3 rays per
// sample that meets a plate (render/glossy_direct.hpp says how), and all run the same spp, so
// the ray counts in plates.csv are equal. Each is compared with a reference (MIS power at
// k_plates_reference_factor times the spp, from sample indices none of the four uses) in 16
// pixel boxes, one round each light's highlight in each plate (render/veach_plates.hpp).
//
// Expected (Veach, fig. 9.2): light sampling wins on rough plates with small lights, BSDF
// sampling on sharp plates with large lights, MIS is close to the better of the two everywhere.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "geometry/camera.hpp"
#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/table.hpp"
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

// The reference's spp per spp of the four: its own variance adds 1/32 of MIS power's to
// every relMSE of a cell (E[(A - R)^2] = Var A + Var R for independent A and R), a bias well
// below the cells' own noise (measured: a cell's relMSE moves by tens of percent between seeds).
inline constexpr int k_plates_reference_factor = 32;
// Rays per pixel sample at most: the camera ray and two more (the rule above).
inline constexpr double k_plates_rays_per_sample = 3.0;

// Rays the study may trace: the four renders and the reference.
inline double plates_predicted_rays(int width, int height, int spp) {
  return static_cast<double>(width) * height * spp * k_plates_rays_per_sample *
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
inline PlatesStudy run_plates_study(int width, int height, int spp, std::uint64_t seed,
                                    int threads) {
  const VeachPlates scene = make_veach_plates();
  const Camera camera(scene.camera, width, height);
  PlatesStudy study{plates_table(), {}, {}};
  std::vector<double> rays_per_pixel;
  const double pixels = static_cast<double>(width) * height;
  for (const GlossyStrategyInfo& s : k_glossy_strategies) {
    const RenderResult r = render(camera, {spp, 0, seed, threads, nullptr},
                                  [&](const Ray& ray, Rng& rng, RayCount& count) {
                                    return estimate_plates_radiance(scene, ray, s.strategy, rng,
                                                                    count);
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
                           std::string(k_glossy_strategies[i].name), rays_per_pixel[i],
                           rel_mse[i], rel_mse[best] > 0.0 ? rel_mse[i] / rel_mse[best] : 1.0,
                           std::string(k_glossy_strategies[best].name)});
  }
  return study;
}

// The console's view of plates.csv: per plate (rows) and light (columns) the winner, and MIS
// power's relMSE over the winner's.
inline std::string plates_console(const PlatesStudy& study) {
  std::string out = "  Veach's plates, winner per plate (rows, rough to sharp) and light (columns, "
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

// plates.png (the four strategies and the reference side by side, each labelled, blown up 2x
// so a highlight a few pixels wide stays visible) and plates.csv.
inline void write_plates(const std::filesystem::path& dir, const PlatesStudy& study, int spp) {
  std::vector<std::string> labels;
  for (const GlossyStrategyInfo& s : k_glossy_strategies) labels.emplace_back(s.label);
  labels.emplace_back(fmt::format("reference ({} spp)", spp * k_plates_reference_factor));
  SheetLayout layout;
  layout.columns = static_cast<int>(study.images.size());
  layout.label_scale = 1;
  layout.title = fmt::format("Veach's plates at equal rays ({} spp, 3 rays a sample): plates "
                             "rough (bottom) to sharp, lights small (left) to large",
                             spp);
  write_png(dir / "plates.png", labelled_grid(study.images, labels, 2, layout));
  write_csv(dir / "plates.csv", study.table);
}

}  // namespace mcrt
