#pragma once
// Choosing a light by power: the floor of render/light_choice.hpp, lit by a bright light and
// one of 1/100 its power, seen from above as a 128 x 64 map, its direct light estimated with the
// light picked uniformly (P_j = 1/2) or by power (P_j = Phi_j / sum Phi) at the same spp: one
// shadow ray a sample, so equal spp is equal rays. Each pixel is the floor point under its
// centre, so the closed form is its exact value and the relMSE has no reference noise in it.
// Both choices read the same random numbers (common random numbers: the comparison is paired).
//
// Expected: power choice nearly noiseless where the bright light dominates, uniform choice
// spending half its samples on the dim light there (relative variance ~1 a sample); beside the
// dim light, where the two shares are close, the other way round.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/rng.hpp"
#include "io/image_file.hpp"
#include "io/labelled_grid.hpp"
#include "io/table.hpp"
#include "render/image.hpp"
#include "render/light_choice.hpp"

namespace mcrt {

inline constexpr int k_light_choice_width = 128, k_light_choice_height = 64;
inline constexpr int k_light_choice_spp = 16;
// Where the dim light gives more than this share of a pixel's light: "beside the dim light".
inline constexpr double k_dim_share = 0.1;

struct LightChoiceStudy {
  Table table;
  std::vector<Image> images;  // uniform, power, exact
};

// relMSE (render/relative_error.hpp's measure) of `a` against `exact` over the pixels `keep`
// says yes to: mean of (A - R)^2 / (R^2 + 0.01).
inline double masked_relative_mse(const Image& a, const Image& exact, const std::vector<bool>& keep,
                                  bool value) {
  double sum = 0.0;
  int pixels = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    if (keep[i] != value) continue;
    const double r = exact.pixels[i].x, d = a.pixels[i].x - r;
    sum += d * d / (r * r + 0.01);
    ++pixels;
  }
  return pixels > 0 ? sum / pixels : 0.0;
}

inline LightChoiceStudy run_light_choice_study(std::uint64_t seed) {
  const TwoLights scene;
  const int w = k_light_choice_width, h = k_light_choice_height;
  LightChoiceStudy study{Table({{"choice", Column::text},
                                {"p_dim", Column::real, 6},
                                {"region", Column::text},
                                {"pixels", Column::integer},
                                {"rays_per_pixel", Column::real, 6},
                                {"rel_mse", Column::real, 6}}),
                         {}};
  Image exact(w, h);
  std::vector<bool> beside_dim(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Vec3 p = scene.floor_point(x + 0.5, y + 0.5, w, h);
      exact.at(x, y) = Color(exact_floor_radiance(scene, p));
      beside_dim[static_cast<std::size_t>(y) * w + x] =
          light_share(scene, 1, p) > k_dim_share * exact_floor_radiance(scene, p);
    }
  int near_pixels = 0;
  for (bool b : beside_dim) near_pixels += b;
  for (LightChoice choice : {LightChoice::uniform, LightChoice::power}) {
    Image image(w, h);
    RayCount count;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Vec3 p = scene.floor_point(x + 0.5, y + 0.5, w, h);
        const std::uint64_t pixel = static_cast<std::uint64_t>(y) * w + x;
        double sum = 0.0;
        for (int s = 0; s < k_light_choice_spp; ++s) {
          Rng rng(seed, stream_index(pixel, static_cast<std::uint64_t>(s)));
          sum += estimate_floor_radiance(scene, p, choice, rng, count);
        }
        image.at(x, y) = Color(sum / k_light_choice_spp);
      }
    const std::string name = choice == LightChoice::uniform ? "uniform" : "power";
    const double p_dim = light_choice_probability(scene, choice, 1);
    const double rays = static_cast<double>(count.rays) / (static_cast<double>(w) * h);
    study.table.add_row(
        {name, p_dim, "all", w * h, rays,
         masked_relative_mse(image, exact, std::vector<bool>(beside_dim.size()), false)});
    study.table.add_row({name, p_dim, "beside_dim", near_pixels, rays,
                         masked_relative_mse(image, exact, beside_dim, true)});
    study.table.add_row({name, p_dim, "rest", w * h - near_pixels, rays,
                         masked_relative_mse(image, exact, beside_dim, false)});
    study.images.push_back(std::move(image));
  }
  study.images.push_back(std::move(exact));
  return study;
}

// light_choice.png (the two choices and the exact image, blown up 3x, each labelled with its
// relMSE) and light_choice.csv.
inline void write_light_choice(const std::filesystem::path& dir, const LightChoiceStudy& study) {
  const auto rel_mse = [&](const char* choice) {
    for (std::size_t i = 0; i < study.table.size(); ++i)
      if (study.table.at(i, "choice").json() == choice &&
          study.table.at(i, "region").json() == "all")
        return study.table.at(i, "rel_mse").json().get<double>();
    return 0.0;
  };
  const std::vector<std::string> labels{fmt::format("uniform, P = 1/2: relMSE {:.3g}",
                                                    rel_mse("uniform")),
                                        fmt::format("by power, P = Phi / sum Phi: relMSE {:.3g}",
                                                    rel_mse("power")),
                                        "exact (closed form)"};
  SheetLayout layout;
  layout.columns = 3;
  layout.title = fmt::format(
      "A floor lit by a bright light (over its left half) and one of 1/100 "
      "its power (beyond its bottom edge, on the right), {} spp",
      k_light_choice_spp);
  write_png(dir / "light_choice.png", labelled_grid(study.images, labels, 3, layout));
  write_csv(dir / "light_choice.csv", study.table);
}

}  // namespace mcrt
