#pragma once
// The shoot-out: every estimator on every scene for the same ray budgets. Each estimator
// renders one image progressively, one sample per pixel per pass, and is photographed the
// first time the rays it has traced (camera, bounce and shadow rays) reach each budget: its
// image then (the mean of the passes so far), spp and rays. Against the scene's reference each
// photograph gives
//   relative MSE (render/relative_error.hpp), efficiency = 1 / (relMSE x rays per pixel),
// and the image mean with a 95% confidence interval, mean +- 1.96 sqrt(sum_i (A_i - R_i)^2) / n
// (the pixels are independent; (A_i - R_i)^2 estimates pixel i's variance plus the
// reference's, which is far smaller). Rays, not seconds: the count is the same on every
// machine and at every thread count, so every number here is too; the seconds each render
// took go to timings.json only.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/camera.hpp"
#include "app/reference_cache.hpp"
#include "io/table.hpp"
#include "render/image.hpp"
#include "render/relative_error.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

#include "estimators.hpp"

namespace mcrt {

// A scene of the shoot-out: a name and, for cornell, a light scale.
struct ShootoutScene {
  std::string scene;
  double light_scale = 1.0;
  std::string label() const {
    return scene == "cornell" ? fmt::format("cornell x{}", light_scale) : scene;
  }
  // For file names: cornell_x0.1, cornell-spheres.
  std::string slug() const {
    return scene == "cornell" ? fmt::format("cornell_x{}", light_scale) : scene;
  }
};

inline std::vector<ShootoutScene> shootout_scenes() {
  // smallpt: its mirror and glass, where light sampling cannot help (the page's "deltas and
  // caustics").
  return {{"furnace", 1.0}, {"cornell", 0.1},         {"cornell", 1.0},
          {"cornell", 3.0}, {"cornell-spheres", 1.0}, {"smallpt", 1.0}};
}

// One photograph of a progressive render.
struct Snapshot {
  int budget = 0;  // rays per pixel
  int spp = 0;
  double seconds = 0.0;  // measured: timings.json only
  std::uint64_t rays = 0;
  Image image;
};

// Passes of 1 spp (pass s takes sample index s) until the rays traced reach every budget
// (ascending, in rays per pixel); the image at each budget. Passes, ray counts and so the spp
// at each budget are the same whatever the machine and the thread count.
template <class Estimate>
std::vector<Snapshot> render_to_budgets(const Camera& camera, std::uint64_t seed, int threads,
                                        const std::vector<int>& budgets, Estimate&& estimate,
                                        RenderTotals& total) {
  std::vector<Snapshot> snapshots;
  Image sum(camera.width(), camera.height());
  const double pixels = static_cast<double>(camera.width()) * camera.height();
  Snapshot now;
  for (std::size_t b = 0; b < budgets.size();) {
    const RenderSettings settings{1, static_cast<std::uint64_t>(now.spp), seed, threads, nullptr};
    const RenderResult pass = render(camera, settings, estimate);
    total.add(pass);
    for (std::size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += pass.image.pixels[i];
    ++now.spp;
    now.seconds += pass.seconds;
    now.rays += pass.rays;
    for (; b < budgets.size() &&
           static_cast<double>(now.rays) >= static_cast<double>(budgets[b]) * pixels;
         ++b) {
      now.budget = budgets[b];
      now.image = sum;
      for (Color& c : now.image.pixels) c /= static_cast<double>(now.spp);
      snapshots.push_back(now);
    }
  }
  return snapshots;
}

// efficiency.csv: nothing measured in seconds (see the top of this file).
inline Table efficiency_table() {
  return Table({{"scene", Column::text},
                {"light_scale", Column::real, 3},
                {"estimator", Column::text},
                {"budget_rays_per_pixel", Column::integer},
                {"spp", Column::integer},
                {"rays_per_pixel", Column::real, 6},
                {"rel_mse", Column::real, 6},
                {"efficiency", Column::real, 6},
                {"efficiency_vs_uniform", Column::real, 6},
                {"mean", Column::real, 6},
                {"mean_ci_low", Column::real, 6},
                {"mean_ci_high", Column::real, 6},
                {"reference_mean", Column::real, 6}});
}

// The seconds of the same photographs, for timings.json: 1 / (relMSE x seconds) depends on the
// machine and its load.
inline Table shootout_seconds_table() {
  return Table({{"scene", Column::text},
                {"light_scale", Column::real, 3},
                {"estimator", Column::text},
                {"budget_rays_per_pixel", Column::integer},
                {"seconds", Column::real, 6},
                {"rays_per_second", Column::real, 6},
                {"efficiency_per_second", Column::real, 6}});
}

// The image mean and the half-width of its 95% confidence interval (see the top of this file).
struct MeanWithInterval {
  double mean = 0.0, half_width = 0.0;
};
inline MeanWithInterval mean_with_interval(const Image& image, const Image& reference) {
  double sum_squares = 0.0;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const double d = average(image.pixels[i]) - average(reference.pixels[i]);
    sum_squares += d * d;
  }
  const double n = static_cast<double>(image.pixels.size());
  return {mean_radiance(image), 1.96 * std::sqrt(sum_squares) / n};
}

// The shoot-out's results: the table and, per scene, the images at the largest budget (one
// per estimator, then the reference).
struct Shootout {
  Table table = efficiency_table();
  Table seconds = shootout_seconds_table();
  std::vector<std::vector<Image>> equal_rays;  // [scene][estimator..., reference]
  RenderTotals total;
};

// Every estimator on one scene; rows appended to `result`.
inline void shoot_out_scene(const ShootoutScene& s, const Reference& reference, const auto& o,
                            Shootout& result) {
  SceneParams params = o.scene.params;
  params.light_scale = s.light_scale;
  const Scene scene = make_scene(s.scene, params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  const double pixels = static_cast<double>(o.image.width) * o.image.height;
  std::vector<Image> images;
  std::vector<double> uniform_efficiency;
  for (const EstimatorInfo& e : k_estimators) {
    const std::vector<Snapshot> shots =
        render_to_budgets(camera, o.common.seed, o.common.threads, o.budgets,
                          make_estimator(e.kind, scene, o.depth), result.total);
    for (std::size_t b = 0; b < shots.size(); ++b) {
      const Snapshot& shot = shots[b];
      const double rel_mse = relative_mse(shot.image, reference.image);
      const double rays_per_pixel = static_cast<double>(shot.rays) / pixels;
      const double efficiency = 1.0 / (rel_mse * rays_per_pixel);
      if (e.kind == EstimatorKind::uniform) uniform_efficiency.push_back(efficiency);
      const MeanWithInterval m = mean_with_interval(shot.image, reference.image);
      result.table.add_row({s.scene, s.light_scale, std::string(e.name), shot.budget, shot.spp,
                            rays_per_pixel, rel_mse, efficiency, efficiency / uniform_efficiency[b],
                            m.mean, m.mean - m.half_width, m.mean + m.half_width,
                            mean_radiance(reference.image)});
      result.seconds.add_row({s.scene, s.light_scale, std::string(e.name), shot.budget,
                              shot.seconds, static_cast<double>(shot.rays) / shot.seconds,
                              1.0 / (rel_mse * shot.seconds)});
    }
    images.push_back(shots.back().image);
  }
  images.push_back(reference.image);
  result.equal_rays.push_back(std::move(images));
}

}  // namespace mcrt
