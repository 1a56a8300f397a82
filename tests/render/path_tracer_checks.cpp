// The path tracer of chapter 05 (common/render/path_tracer.hpp) against closed forms and against an
// independent renderer:
//  - furnace: the mean radiance after k bounces is Le (1 - a^(k+1)) / (1 - a) (z-tests for
//    several a and k) and its variance is furnace_radiance_variance (z-tests of the sample
//    variance);
//  - the RMS error of an image falls as spp^-1/2 (a z-test of the fitted slope), and the
//    two-render error that chapters 04, 05 and 07 report estimates Var[L] / spp (a z-test in
//    the furnace, where Var[L] is known);
//  - cornell-spheres agrees, tile by tile and in every channel, with a path tracer written
//    here from scratch.
// Every check is designed for a false-failure rate alpha = 1e-4.

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "geometry/camera.hpp"
#include "integration/statistics.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "render/two_render_error.hpp"
#include "stats/check.hpp"
#include "stats/hypothesis.hpp"
#include "support/color_moments.hpp"
#include "render/path_tracer_furnace.hpp"
#include "render/two_render_error_check.hpp"

namespace {

using namespace mcrt;
using mcrt::testing::FurnaceSetup;

// ---------------------------------------------------------------------------------------------
// Furnace: the mean.

constexpr int k_furnace_paths = 40000;

double furnace_mean_check(std::uint64_t seed, std::uint64_t block, const FurnaceSetup& setup) {
  const RunningStats samples = mcrt::testing::furnace_samples(setup, k_furnace_paths, seed, block,
                                                              mcrt::testing::chapter_path_tracer);
  return mcrt::testing::furnace_mean_p_value(setup, samples);
}

// A different block of streams per check keeps the checks independent of each other.
MCRT_STATISTICAL_CHECK(path_tracer_furnace_mean_a05_k1, 1e-4) {
  return furnace_mean_check(seed, 1, {0.5, 1.0, 1});
}
MCRT_STATISTICAL_CHECK(path_tracer_furnace_mean_a05_k4, 1e-4) {
  return furnace_mean_check(seed, 2, {0.5, 1.0, 4});
}
MCRT_STATISTICAL_CHECK(path_tracer_furnace_mean_a08_k10, 1e-4) {
  return furnace_mean_check(seed, 3, {0.8, 2.0, 10});
}
MCRT_STATISTICAL_CHECK(path_tracer_furnace_mean_a095_k3, 1e-4) {
  return furnace_mean_check(seed, 4, {0.95, 0.5, 3});
}
MCRT_STATISTICAL_CHECK(path_tracer_furnace_mean_a02_k2, 1e-4) {
  return furnace_mean_check(seed, 5, {0.2, 3.0, 2});
}

// ---------------------------------------------------------------------------------------------
// Furnace: the variance. The samples are not normal, so the chi-square variance test does not
// apply; the suite's variance z-test (stats/hypothesis.hpp) takes their kurtosis from the same
// samples (consistent, and the samples are bounded, so every moment exists). At n = 4e4 the
// sample variance is close to normal (CLT), so the test holds its false-failure rate.

double furnace_variance_check(std::uint64_t seed, std::uint64_t block, const FurnaceSetup& setup) {
  const std::vector<double> values =
      mcrt::testing::furnace_radiance_values(setup, k_furnace_paths, seed, block);
  const double expected = furnace_radiance_variance(setup.albedo, setup.emission, setup.depth);
  return mcrt::testing::variance_z_test_p_value(values, expected);
}

MCRT_STATISTICAL_CHECK(path_tracer_furnace_variance_a05_k4, 1e-4) {
  return furnace_variance_check(seed, 11, {0.5, 1.0, 4});
}
MCRT_STATISTICAL_CHECK(path_tracer_furnace_variance_a09_k8, 1e-4) {
  return furnace_variance_check(seed, 12, {0.9, 1.0, 8});
}

// ---------------------------------------------------------------------------------------------
// RMS error against spp. For independent renders A, B of n samples per pixel,
// E[(A - B)^2 / 2] = Var[A] = sigma_p^2 / n exactly, so the mean squared error MSE(n) over the
// image falls exactly as 1/n and log RMSE against log n has slope -1/2.
//
// The test: at each n, MSE(n) is the mean of d_p = (A_p - B_p)^2 / 2 over P independent
// pixels, so log MSE(n) has variance v = Var(d) / (P MSE^2) (delta method, Var(d) estimated
// from the pixels). A weighted least-squares fit of log MSE on log n with weights 1/v has a
// slope with standard error 1 / sqrt(sum w (x - mean_w x)^2); the RMSE slope is half of it.
// z-test of that slope against -1/2. Every render uses its own sample range, so all levels
// are independent. The log's bias (-v/2, Jensen) differs between levels by about 1e-3 in the
// slope, far below its standard error (about 0.02).

// An image of `spp` paths per pixel from samples [first_sample, first_sample + spp): the
// chapter's own render loop, so the check covers it too.
Image render_image(const Camera& camera, const Scene& scene, int depth, int spp,
                   std::uint64_t first_sample, std::uint64_t seed) {
  const RenderSettings settings{spp, first_sample, seed, 1, nullptr};
  return render(camera, settings,
                [&](const Ray& ray, Rng& rng, RayCount& count) {
                  return estimate_path_radiance(scene, ray, depth, rng, count);
                })
      .image;
}

MCRT_STATISTICAL_CHECK(path_tracer_rmse_slope_is_minus_one_half, 1e-4) {
  const Scene scene = make_cornell_spheres();
  const Camera camera(scene.camera, 32, 24);
  const int depth = 4;
  double sum_w = 0.0, sum_wx = 0.0, sum_wy = 0.0, sum_wxx = 0.0, sum_wxy = 0.0;
  std::uint64_t first_sample = 0;
  for (int spp : {4, 8, 16, 32, 64}) {
    const auto n = static_cast<std::uint64_t>(spp);
    const Image a = render_image(camera, scene, depth, spp, first_sample, seed);
    const Image b = render_image(camera, scene, depth, spp, first_sample + n, seed);
    first_sample += 2 * n;

    RunningStats d;
    for (std::size_t p = 0; p < a.pixels.size(); ++p) {
      const Color diff = a.pixels[p] - b.pixels[p];
      d.add(glm::dot(diff, diff) / 6.0);  // (A - B)^2 / 2, averaged over the 3 channels
    }
    const double mse = d.mean();
    const double v = d.variance() / (static_cast<double>(d.count()) * mse * mse);
    const double x = std::log(static_cast<double>(spp)), y = std::log(mse), w = 1.0 / v;
    sum_w += w;
    sum_wx += w * x;
    sum_wy += w * y;
    sum_wxx += w * x * x;
    sum_wxy += w * x * y;
  }
  const double sxx = sum_wxx - sum_wx * sum_wx / sum_w;
  const double mse_slope = (sum_wxy - sum_wx * sum_wy / sum_w) / sxx;
  return mcrt::testing::z_test_p_value(mse_slope / 2.0, -0.5, 0.5 / std::sqrt(sxx));
}

// ---------------------------------------------------------------------------------------------
// The two-render error of the chapters estimates Var[L] / spp in the furnace: the procedure and
// its false-failure rate are in tests/render/two_render_error_check.hpp.
MCRT_STATISTICAL_CHECK(two_render_error_estimates_the_furnace_variance_over_spp, 1e-4) {
  return mcrt::testing::two_render_error_p_value(seed, two_render_mean_squared_error);
}

// ---------------------------------------------------------------------------------------------
// An independent renderer of cornell-spheres. Written here from scratch, sharing only the
// scene's data and the camera (the camera is tested on its own; the subject here is the
// radiance): its own ray-sphere intersection (the geometric form: the closest approach of the
// ray to the centre), its own orthonormal basis, and cosine-weighted directions
// (pdf cos(theta)/pi, so the path weight is multiplied by the albedo alone) instead of uniform
// ones. It cuts paths at the same depth, so both estimate the same radiance.

struct ReferenceSphere {
  Vec3 center;
  double radius;
  Color albedo;
  Color emission;
};

struct ReferenceHit {
  double t;
  std::size_t sphere;
};

// Closest approach: tca = (c - o).d, squared distance of the line from c is |c - o|^2 - tca^2;
// the hits are tca -+ sqrt(r^2 - that). Hits nearer than 1e-4 are ignored (the ray's own start
// point; 1e-4 is far above the round-off of coordinates below 1e5 and far below any feature).
std::optional<ReferenceHit> reference_hit(const std::vector<ReferenceSphere>& spheres,
                                          const Vec3& o, const Vec3& d) {
  std::optional<ReferenceHit> best;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const Vec3 l = spheres[i].center - o;
    const double tca = l.x * d.x + l.y * d.y + l.z * d.z;
    const double half_chord2 =
        spheres[i].radius * spheres[i].radius - ((l.x * l.x + l.y * l.y + l.z * l.z) - tca * tca);
    if (half_chord2 < 0.0) continue;
    const double thc = std::sqrt(half_chord2);
    double t = tca - thc;
    if (t <= 1e-4) t = tca + thc;
    if (t > 1e-4 && (!best || t < best->t)) best = ReferenceHit{t, i};
  }
  return best;
}

Color reference_radiance(const std::vector<ReferenceSphere>& spheres, Vec3 o, Vec3 d, int depth,
                         Rng& rng) {
  Color sum(0.0), weight(1.0);
  for (int bounce = 0; bounce <= depth; ++bounce) {
    const std::optional<ReferenceHit> hit = reference_hit(spheres, o, d);
    if (!hit) break;
    const ReferenceSphere& s = spheres[hit->sphere];
    const Vec3 p = o + hit->t * d;
    Vec3 n = (p - s.center) / s.radius;
    if (n.x * d.x + n.y * d.y + n.z * d.z > 0.0) n = -n;  // the side the ray came from
    sum += weight * s.emission;
    // Cosine-weighted direction: a uniform point on the disk lifted to the hemisphere.
    const double r = std::sqrt(rng.uniform()), phi = k_two_pi * rng.uniform();
    const double lx = r * std::cos(phi), ly = r * std::sin(phi);
    const double lz = std::sqrt(std::max(0.0, 1.0 - lx * lx - ly * ly));
    // A basis around n from the cross product with the axis least aligned with it.
    const Vec3 helper = std::abs(n.x) > 0.5 ? Vec3(0, 1, 0) : Vec3(1, 0, 0);
    const Vec3 tangent = glm::normalize(glm::cross(helper, n));
    const Vec3 bitangent = glm::cross(n, tangent);
    d = glm::normalize(lx * tangent + ly * bitangent + lz * n);
    o = p;
    weight *= s.albedo;  // f_r cos / pdf = (rho / pi) cos / (cos / pi)
  }
  return sum;
}

// Tiles of the image: every sample picks a uniformly random point of its tile, so the mean of
// a tile's samples estimates the tile's mean radiance (RGB) with the plain sample covariance.
// Two renderers, n samples per tile each: the difference d of their mean colours has
// covariance S = C1/n + C2/n, and d' S^-1 d is chi-square with 3 degrees of freedom if both
// are unbiased (n = 1.5e4: CLT, and S is estimated to about 1%). The tiles' samples are
// independent, so the Sidak correction over the 6 tiles is exact: the check returns the
// smallest tile p-value rescaled to the family, 1 - (1 - p_min)^6, and its alpha is the
// family-wise false-failure rate.
MCRT_STATISTICAL_CHECK_AT_MOST(path_tracer_agrees_with_independent_renderer_cornell_spheres, 1e-4) {
  const Scene scene = make_cornell_spheres();
  std::vector<ReferenceSphere> spheres;
  for (const Sphere& s : scene.spheres())
    spheres.push_back({s.center, s.radius, scene.materials[s.material].albedo,
                       scene.materials[s.material].emission});
  constexpr int k_tiles_x = 3, k_tiles_y = 2, k_tile_size = 16, k_samples = 15000, k_depth = 4;
  constexpr int k_tiles = k_tiles_x * k_tiles_y;
  const Camera camera(scene.camera, k_tiles_x * k_tile_size, k_tiles_y * k_tile_size);

  double p_min = 1.0;
  for (int tile = 0; tile < k_tiles; ++tile) {
    const double x0 = (tile % k_tiles_x) * k_tile_size, y0 = (tile / k_tiles_x) * k_tile_size;
    mcrt::testing::ColorMoments ours, reference;
    RayCount count;
    for (int i = 0; i < k_samples; ++i) {
      // Streams (2 tile, i) for the path tracer, (2 tile + 1, i) for the reference.
      const auto block = 2 * static_cast<std::uint64_t>(tile);
      Rng rng(seed, stream_index(block, i));
      const Vec2 u = rng.uniform2();
      const Ray ray = camera.generate_ray(x0 + k_tile_size * u.x, y0 + k_tile_size * u.y);
      ours.add(estimate_path_radiance(scene, ray, k_depth, rng, count));
      Rng reference_rng(seed, stream_index(block + 1, i));
      const Vec2 v = reference_rng.uniform2();
      const Ray reference_ray = camera.generate_ray(x0 + k_tile_size * v.x, y0 + k_tile_size * v.y);
      reference.add(reference_radiance(spheres, reference_ray.origin, reference_ray.direction,
                                       k_depth, reference_rng));
    }
    const Vec3 d = ours.mean() - reference.mean();
    const glm::dmat3 s = ours.covariance_of_mean() + reference.covariance_of_mean();
    const double chi_square = glm::dot(d, glm::inverse(s) * d);
    p_min = std::min(p_min, mcrt::testing::chi_square_upper_tail(chi_square, 3.0));
  }
  return -std::expm1(k_tiles * std::log1p(-p_min));  // 1 - (1 - p_min)^tiles, without round-off
}

}  // namespace
