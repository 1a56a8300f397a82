#pragma once
// What a4's checks ask of a path tracer, produced in bulk: `radiance(scene, ray, max_depth,
// rng, count)` as estimate_path_radiance. LocalSubject answers a4's requests with these (the
// student's tracer); the checks run them on the instructor's reference and diagnosis_test.cpp
// on known-wrong tracers. No test and no verdict here: the subject program includes it.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "integration/statistics.hpp"
#include "assignments/subject/requests.hpp"
#include "render/pixel_estimate.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"

namespace mcrt::testing::assignment {

/// A small scene lit by a white sky (a large emitting sphere, Le = 1) that every escaping
/// direction of a uniform sampler finds, so renders of a few hundred paths per pixel have small
/// errors: a red ball on a grey ground, seen from slightly above.
inline Scene make_sky_scene() {
  Scene scene;
  scene.name = "sky";
  const auto sky = scene.add_material({Color(0.0), Color(1.0)});
  const auto ground = scene.add_material({Color(0.5), Color(0.0)});
  const auto ball = scene.add_material({Color(0.7, 0.3, 0.2), Color(0.0)});
  scene.add_sphere({Vec3(0.0), 100.0, sky});
  scene.add_sphere({Vec3(0.0, -1001.0, 0.0), 1000.0, ground});
  scene.add_sphere({Vec3(0.0), 1.0, ball});
  scene.camera = {Vec3(0.0, 0.5, 4.0), Vec3(0.0, -0.15, -1.0), Vec3(0.0, 1.0, 0.0), 0.9, 0.0};
  return scene;
}

/// Values of `radiance` for n paths from the furnace's centre in uniformly random directions.
template <class Radiance>
std::vector<double> furnace_values(Radiance&& radiance, double albedo, int depth, int n,
                                   std::uint64_t seed, std::uint64_t block) {
  const Scene furnace = make_furnace(albedo, 1.0);
  std::vector<double> values;
  RayCount count;
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, stream_index(block, static_cast<std::uint64_t>(i)));
    const Ray ray{Vec3(0.0), sample_uniform_sphere(rng.uniform2())};
    values.push_back(average(radiance(furnace, ray, depth, rng, count)));
  }
  return values;
}

/// The mean channel radiance of `estimate` per region x region block of a Size x Size image:
/// spp samples per pixel, sample s of pixel p drawn from the stream (p, s).
template <int Size, int Region, class Estimate>
std::array<RunningStats, (Size / Region) * (Size / Region)> region_stats(const Camera& camera,
                                                                         Estimate&& estimate,
                                                                         int spp,
                                                                         std::uint64_t seed) {
  constexpr int regions = Size / Region;
  std::array<RunningStats, regions * regions> stats;
  RayCount count;
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
      for (int s = 0; s < spp; ++s) {
        Rng rng(seed, stream_index(static_cast<std::uint64_t>(y * Size + x),
                                   static_cast<std::uint64_t>(s)));
        const Ray ray = camera.generate_ray(x, y, rng.uniform2());
        stats[static_cast<std::size_t>((y / Region) * regions + x / Region)].add(
            average(estimate(ray, rng, count)));
      }
  return stats;
}

/// Region statistics of per-sample values listed in region_stats's order (rows, pixels,
/// samples), added in that order so that they equal region_stats's; a missing value is NaN.
template <int Size, int Region>
std::array<RunningStats, (Size / Region) * (Size / Region)> stats_by_region(
    const std::vector<double>& values, int spp) {
  constexpr int regions = Size / Region;
  std::array<RunningStats, regions * regions> stats;
  std::size_t i = 0;
  for (int y = 0; y < Size; ++y)
    for (int x = 0; x < Size; ++x)
      for (int s = 0; s < spp; ++s, ++i)
        stats[static_cast<std::size_t>((y / Region) * regions + x / Region)].add(
            i < values.size() ? values[i] : std::nan(""));
  return stats;
}

/// The channel-mean radiance(scene, ray, rng, count) of every camera sample of `scene` at
/// size x size pixels and spp per pixel, in the order region_stats adds them: rows, then
/// pixels, then samples, each sample on its own stream of `seed`.
template <class Radiance>
std::vector<double> every_pixel_sample(const Scene& scene, int size, int spp, std::uint64_t seed,
                                       Radiance&& radiance) {
  const Camera camera(scene.camera, size, size);
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(size * size * spp));
  RayCount count;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int s = 0; s < spp; ++s) {
        Rng rng(seed, stream_index(static_cast<std::uint64_t>(y * size + x),
                                   static_cast<std::uint64_t>(s)));
        const Ray ray = camera.generate_ray(x, y, rng.uniform2());
        values.push_back(average(radiance(scene, ray, rng, count)));
      }
  return values;
}

/// Every sample of the sky scene at depth k (every_pixel_sample).
template <class Radiance>
std::vector<double> sky_values(Radiance&& radiance, int size, int k, int spp, std::uint64_t seed) {
  return every_pixel_sample(make_sky_scene(), size, spp, seed,
                            [&](const Scene& scene, const Ray& ray, Rng& rng, RayCount& count) {
                              return radiance(scene, ray, k, rng, count);
                            });
}

/// One path of `radiance` in the furnace (albedo, emission) from its centre along `direction`,
/// drawn from Rng(seed, stream): its channel-mean radiance and its rays.

template <class Radiance>
PathSample furnace_path(Radiance&& radiance, double albedo, double emission, Vec3 direction,
                        int depth, std::uint64_t seed, std::uint64_t stream) {
  const Scene furnace = make_furnace(albedo, emission);
  Rng rng(seed, stream);
  RayCount count;
  const double L = average(radiance(furnace, {Vec3(0.0), direction}, depth, rng, count));
  return {L, count.rays};
}

// a4.2, the pixel's estimate. `estimate(camera, x, y, spp, radiance, rng)` is estimate_pixel
// (the student's, or a known-wrong one in diagnosis_test.cpp).

/// The camera of a4.2's checks: 8 x 6 pixels with a wide field of view, so that the ray
/// directions vary visibly inside one pixel.
inline Camera pixel_camera() {
  return Camera(CameraSpec{Vec3(0.0), Vec3(0.2, -0.1, -1.0), Vec3(0.0, 1.0, 0.0), 1.4, 0.0}, 8, 6);
}

/// A radiance known in closed form per ray, positive, different in every channel and varying across a
/// pixel: what the exact check passes as `radiance` (it never draws from the rng, so the
/// samples' u are the rng's only draws).
inline Color direction_radiance(const Ray& ray) {
  const Vec3 d = ray.direction;
  return Color(30.0 + 20.0 * d.x, 2.0 + 30.0 * d.y * d.y, std::exp(3.0 * d.x - 2.0 * d.y));
}

/// The stream of pixel (x, y) of a width-wide image in a4.2's requests.
inline std::uint64_t pixel_stream(int x, int y, int width) {
  return static_cast<std::uint64_t>(y * width + x);
}

/// Every pixel of pixel_camera() estimated with direction_radiance at spp samples, pixel
/// (x, y) from Rng(seed, pixel_stream): four numbers a pixel (mean r, g, b, standard error),
/// rows then pixels.
template <class Estimate>
std::vector<double> pixel_exact_values(Estimate&& estimate, int spp, std::uint64_t seed) {
  const Camera camera = pixel_camera();
  std::vector<double> out;
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      Rng rng(seed, pixel_stream(x, y, camera.width()));
      const PixelEstimate e = estimate(
          camera, x, y, spp, [](const Ray& ray, Rng&) { return direction_radiance(ray); }, rng);
      for (double v : {e.mean.r, e.mean.g, e.mean.b, e.standard_error}) out.push_back(v);
    }
  return out;
}

/// The directions of the rays estimate() traces for pixel (x, y) of pixel_camera() at spp
/// samples from Rng(seed, stream), in the order it traces them (a radiance that records them).
template <class Estimate>
std::vector<Vec3> pixel_ray_directions(Estimate&& estimate, int x, int y, int spp,
                                       std::uint64_t seed, std::uint64_t stream) {
  const Camera camera = pixel_camera();
  std::vector<Vec3> directions;
  directions.reserve(static_cast<std::size_t>(spp));
  Rng rng(seed, stream);
  estimate(
      camera, x, y, spp,
      [&directions](const Ray& ray, Rng&) {
        directions.push_back(ray.direction);
        return Color(0.0);
      },
      rng);
  return directions;
}

/// The value of one furnace path (albedo a, Le = 1, at most k bounces) as a uniform-hemisphere
/// tracer's law gives it, drawn directly: L = sum over j = 0..k of prod over i <= j of 2 a c_i,
/// c_i uniform on [0,1) (the cosines), so E[L] = (1 - a^(k+1)) / (1 - a) = furnace_radiance.
/// a4.2's calibration test traces it instead of the student's estimate_path_radiance, so that
/// a4.2 is graded whatever a4.1 does (and in a kit where a4.1 is still a stub).
inline double furnace_path_law(double albedo, int depth, Rng& rng) {
  double L = 1.0, beta = 1.0;
  for (int j = 1; j <= depth; ++j) {
    beta *= 2.0 * albedo * rng.uniform();
    L += beta;
  }
  return L;
}

/// Every pixel of a size x size image of the furnace (furnace_path_law at albedo, depth), each
/// estimated from spp samples, pixel (x, y) from Rng(seed, pixel_stream): two numbers a pixel
/// (the channel-mean mean, the standard error).
template <class Estimate>
std::vector<double> pixel_furnace_values(Estimate&& estimate, double albedo, int depth, int size,
                                         int spp, std::uint64_t seed) {
  const Scene furnace = make_furnace(albedo, 1.0);
  const Camera camera(furnace.camera, size, size);
  std::vector<double> out;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      Rng rng(seed, pixel_stream(x, y, size));
      const PixelEstimate e = estimate(
          camera, x, y, spp,
          [&](const Ray&, Rng& r) { return Color(furnace_path_law(albedo, depth, r)); }, rng);
      out.push_back(average(e.mean));
      out.push_back(e.standard_error);
    }
  return out;
}

}  // namespace mcrt::testing::assignment
