// Chapter 01: plain ray tracing.
//
//   for each sample:
//     shoot a ray into the scene
//     find the closest intersection
//     get the shaded colour at the intersection point (direct light only)
//     set the sample colour to it
//
// Light reaches a surface only straight from the point light: no bounces, so no colour bleeding
// and a ceiling lit by nothing but the lamp's own glow.

#include <fmt/format.h>

#include "falloff.hpp"
#include "app/cli.hpp"
#include "io/image_file.hpp"
#include "app/memory_limit.hpp"
#include "io/output.hpp"
#include "app/ray_limit.hpp"
#include "app/render_summary.hpp"
#include "app/summary.hpp"
#include "render/render.hpp"
#include "render/render_totals.hpp"
#include "render/scene.hpp"

using namespace mcrt;

namespace {

const Chapter k_chapter{"ch01_ray_tracing",
                        "Chapter 01: plain ray tracing. One camera ray per sample, the closest "
                        "hit, shaded by direct light from a point light (no bounces)."};

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{640, 480};
  int spp = 4;  // jittered samples per pixel (anti-aliasing only: there is nothing else to sample)
};

// At most one camera ray and one shadow ray per sample.
RayWork predicted_work(const Options& o) {
  return {2.0 * o.spp * o.image.width * o.image.height, "2 rays (camera + shadow) x spp x pixels"};
}

// Direct light at a hit x from a point light at distance r whose intensity is the area light's
// far field, I(theta_l) = Le A cos(theta_l) about the lamp's normal:
//   L = Le(x) + f_r * I * cos(theta) / r^2   if the shadow ray reaches the light, else Le(x).
Color shade(const Scene& scene, const Hit& hit, RayCount& count) {
  const Material& material = scene.material(hit);
  Color radiance = material.emission;
  const PointLight& light = scene.point_light;
  if (light.intensity == Color(0.0)) return radiance;
  const auto [shadow_ray, distance] = spawn_ray_to(hit, light.position);
  const double cos_theta = glm::dot(hit.normal, shadow_ray.direction);
  if (cos_theta <= 0.0) return radiance;  // the light is behind the surface
  ++count.rays;
  if (scene.any_hit(shadow_ray, {1e-9, distance})) return radiance;  // in shadow
  return radiance + material.brdf() * light.intensity_towards(-shadow_ray.direction) * cos_theta /
                        (distance * distance);
}

// The colour of one camera ray: the shaded closest hit, or black if it leaves the scene.
Color trace(const Scene& scene, const Ray& ray, RayCount& count) {
  ++count.rays;
  const std::optional<Hit> hit = scene.closest_hit(ray);
  return hit ? shade(scene, *hit, count) : Color(0.0);
}

void write_summary(const CLI::App& app, const Options& o, const RenderResult& result,
                   const std::optional<Falloff>& falloff) {
  Json summary = start_summary(k_chapter.name, o.common.seed);
  add_render_setup(summary, o.scene, o.image);
  summary["spp"] = o.spp;
  add_render_totals(summary, totals_of(result));
  summary["mean_radiance"] = mean_radiance(result.image);
  if (falloff)  // the inverse-square and cos^4 laws below the lamp (falloff.hpp)
    summary["falloff"] = {{"height", falloff->height},
                          {"predicted_below_lamp", falloff->predicted_below},
                          {"measured_below_lamp", falloff->measured_below},
                          {"points", falloff->points},
                          {"largest_angle_degrees", falloff->largest_angle},
                          {"largest_relative_deviation", falloff->largest_deviation}};
  summary["flags"] = flags_json(app);
  write_json(o.common.dir / "summary.json", summary);
  Json timings = start_timings(k_chapter.name, o.common.threads);
  add_render_timings(timings, totals_of(result));
  write_timings(o.common.dir, timings, run_flags_json(app));
}

void print_summary(const Options& o, const RenderResult& result,
                   const std::optional<Falloff>& falloff) {
  fmt::print("{}  scene {}  {}x{}  {} spp  {} threads\n", k_chapter.name, o.scene.scene,
             o.image.width, o.image.height, o.spp, o.common.threads);
  fmt::print("  rays traced      {} (camera + shadow)\n", result.rays);
  fmt::print("  time             {:.3f} s\n", result.seconds);
  fmt::print("  rays per second  {:.3g}\n", result.rays_per_second());
  fmt::print("  mean radiance    {:.4f}\n", mean_radiance(result.image));
  if (falloff)
    fmt::print(
        "  below the lamp   {:.6g} (predicted (rho/pi) Le A / h^2 = {:.6g}); cos^4 law at "
        "{} floor points to {} degrees: largest deviation {:.1e}\n",
        falloff->measured_below, falloff->predicted_below, falloff->points, falloff->largest_angle,
        falloff->largest_deviation);
  fmt::print("  wrote            {}/{{image.png,image.pfm,summary.json,timings.json}}\n",
             o.common.out.string());
}

void run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  check_ray_limit(predicted_work(o), k_max_rays, "--spp, --width, --height", o.common.threads,
                  "lower one of them");
  // At most 3 images at once (measured: 36 bytes per pixel at 1024x512).
  check_memory_limit(images_in_memory(static_cast<double>(o.image.width) * o.image.height, 3.0,
                                      o.common.threads, "3 images of --width x --height"),
                     "--width, --height", "lower them");
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);

  ProgressBar progress("ch01 rendering", static_cast<std::uint64_t>(o.image.height),
                       o.common.quiet);
  RenderSettings settings{o.spp, 0, o.common.seed, o.common.threads, &progress};
  const RenderResult result = render(camera, settings, [&](const Ray& ray, Rng&, RayCount& count) {
    return trace(scene, ray, count);
  });
  progress.finish();

  write_png(o.common.dir / "image.png", result.image);
  write_pfm(o.common.dir / "image.pfm", result.image);
  const std::optional<Falloff> falloff = measure_falloff(scene, shade);
  write_summary(app, o, result, falloff);
  if (!o.common.quiet) print_summary(o, result, falloff);
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  ChapterApp app(k_chapter, o.common);
  add_render_options(app, o.scene, o.image);
  add_number_option(app, "--spp", o.spp, "Jittered samples per pixel", 1, 1 << 16);
  return app.run(argc, argv, [&] { run(app, o); });
}
