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

#include <cstdio>
#include <iostream>

#include "io/cli.hpp"
#include "io/image_file.hpp"
#include "io/output.hpp"
#include "io/summary.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"

using namespace mcrt;

namespace {

struct Options {
  CommonOptions common;
  SceneOptions scene;
  ImageOptions image{640, 480};
  int spp = 4;  // jittered samples per pixel (anti-aliasing only: there is nothing else to sample)
};

// Direct light at a hit x from an isotropic point light of intensity I at distance r:
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
  return radiance + material.brdf() * light.intensity * cos_theta / (distance * distance);
}

// The colour of one camera ray: the shaded closest hit, or black if it leaves the scene.
Color trace(const Scene& scene, const Ray& ray, RayCount& count) {
  ++count.rays;
  const std::optional<Hit> hit = scene.closest_hit(ray);
  return hit ? shade(scene, *hit, count) : Color(0.0);
}

int run(const CLI::App& app, const Options& o) {
  check_image_size(o.image);
  const Scene scene = make_scene(o.scene.scene, o.scene.params);
  const Camera camera(scene.camera, o.image.width, o.image.height);
  prepare_output_dir(o.common.out);

  ProgressBar progress("ch01 rendering", static_cast<std::uint64_t>(o.image.height), o.common.quiet);
  RenderSettings settings{o.spp, 0, o.common.seed, o.common.threads, &progress};
  const RenderResult result =
      render(camera, settings, [&](const Ray& ray, Rng&, RayCount& count) {
        return trace(scene, ray, count);
      });
  progress.finish();

  write_png(o.common.out / "image.png", result.image);
  write_pfm(o.common.out / "image.pfm", result.image);
  Json summary;
  summary["chapter"] = "ch01_ray_tracing";
  summary["scene"] = o.scene.scene;
  summary["width"] = o.image.width;
  summary["height"] = o.image.height;
  summary["spp"] = o.spp;
  summary["seed"] = o.common.seed;
  summary["threads"] = o.common.threads;
  summary["rays"] = result.rays;
  summary["seconds"] = result.seconds;
  summary["rays_per_second"] = result.rays_per_second();
  summary["mean_radiance"] = mean_radiance(result.image);
  summary["non_finite_samples"] = result.non_finite_samples;
  summary["flags"] = flags_json(app);
  write_json(o.common.out / "summary.json", summary);

  if (!o.common.quiet) {
    std::printf("ch01_ray_tracing  scene %s  %dx%d  %d spp  %d threads\n", o.scene.scene.c_str(),
                o.image.width, o.image.height, o.spp, o.common.threads);
    std::printf("  rays traced      %llu (camera + shadow)\n",
                static_cast<unsigned long long>(result.rays));
    std::printf("  time             %.3f s\n", result.seconds);
    std::printf("  rays per second  %.3g\n", result.rays_per_second());
    std::printf("  mean radiance    %.4f\n", mean_radiance(result.image));
    std::printf("  wrote            %s/{image.png,image.pfm,summary.json}\n",
                o.common.out.string().c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Chapter 01: plain ray tracing. One camera ray per sample, the closest hit, "
               "shaded by direct light from a point light (no bounces).",
               "ch01_ray_tracing"};
  Options o;
  add_common_options(app, o.common, Chapter{"ch01_ray_tracing", ""});
  add_scene_options(app, o.scene);
  add_image_options(app, o.image);
  app.add_option("--spp", o.spp, "Jittered samples per pixel")->check(CLI::Range(1, 1 << 16));
  return run_chapter(app, argc, argv, [&] { return run(app, o); });
}
