#pragma once
// Procedures shared by tests/render/next_event_estimation_checks.cpp and tests/render/next_event_estimation_test.cpp (which shows they
// reject the known-wrong estimators of render/next_event_estimation_known_bugs.hpp). Each returns a p-value.

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/light_sampling.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "sampling/hemisphere.hpp"
#include "sampling/light.hpp"
#include "stats/hypothesis.hpp"
#include "stats/sampler_tests.hpp"
#include "support/color_moments.hpp"

namespace mcrt::testing {

inline constexpr std::uint64_t k_quad_light_stream = 40;
inline constexpr std::uint64_t k_cap_light_stream = 41;

/// The lamp of `cornell` at light scale 1 (130 x 105, normal down).
inline Quad cornell_lamp() {
  const Scene scene = make_cornell_box();
  return scene.quads()[scene.emitters()[0].index];
}

/// Chi-square of sample_quad's pdf per unit AREA: a point's edge coordinates (a, b) mapped to
/// the square [-1,1]^2, where dA = (A / 4) dx dy, so the density there is p_A A / 4.
/// `pdf_area` is the pdf under test (quad_pdf_area, or a wrong one).
template <class PdfArea>
double quad_light_pdf_p_value(std::uint64_t seed, PdfArea&& pdf_area) {
  const Quad q = cornell_lamp();
  const auto sample = [&](Vec2 u) {
    const Vec3 p = sample_quad(q.corner(), q.edge_u(), q.edge_v(), u).point - q.corner();
    return Vec2(2.0 * q.coordinate_a(p) - 1.0, 2.0 * q.coordinate_b(p) - 1.0);
  };
  const auto density = [&](Vec2) { return pdf_area(q.area()) * q.area() / 4.0; };
  return square_sampler_p_value(sample, density, seed, k_quad_light_stream, "quad light (area)");
}

/// The same for sample_sphere_cap on cornell-spheres' light cap (R = 600, h = 0.27): a point's
/// (phi, z) (z = (p - c).axis / R in [1 - h/R, 1]) mapped to [-1,1]^2, where
/// dA = R^2 dphi dz = (pi R h / 2) dx dy, so the density is p_A pi R h / 2.
template <class PdfArea>
double cap_light_pdf_p_value(std::uint64_t seed, PdfArea&& pdf_area) {
  const Vec3 centre(50, 681.6 - 0.27, 81.6), axis(0, -1, 0);
  const double radius = 600.0, height = 0.27, z0 = 1.0 - height / radius;
  const Frame frame(axis);
  const auto sample = [&](Vec2 u) {
    const Vec3 d = (sample_sphere_cap(centre, radius, axis, height, u).point - centre) / radius;
    const Vec3 local(glm::dot(d, frame.tangent), glm::dot(d, frame.bitangent),
                     glm::dot(d, frame.normal));
    double phi = std::atan2(local.y, local.x);
    if (phi < 0.0) phi += k_two_pi;
    return Vec2(phi / k_pi - 1.0, 2.0 * (local.z - z0) / (1.0 - z0) - 1.0);
  };
  const auto density = [&](Vec2) {
    return pdf_area(radius, height) * k_pi * radius * height / 2.0;
  };
  return square_sampler_p_value(sample, density, seed, k_cap_light_stream, "sphere cap (area)");
}

/// cornell-spheres' light, and a point between its ceiling and that light (above the ceiling
/// plane, beside the left wall), where the top rows' camera rays arrive.
inline Sphere cornell_spheres_light() { return make_cornell_spheres().spheres().back(); }
inline const Vec3 k_above_ceiling(1.5, 83.0, 150.0);

/// Chi-square of sample_sphere_cone from k_above_ceiling: a direction's cos(theta) about the
/// axis to the centre, in [cos(theta_max), 1], and its phi, mapped to [-1,1]^2, where
/// dw = dcos dphi = (pi (1 - cos(theta_max)) / 2) dx dy: the density is
/// p_w pi (1 - cos(theta_max)) / 2. `pdf_solid_angle(centre, radius, x)` is the pdf under test.
template <class PdfSolidAngle>
double cone_light_p_value(std::uint64_t seed, PdfSolidAngle&& pdf_solid_angle) {
  const Sphere light = cornell_spheres_light();
  const Vec3& x = k_above_ceiling;
  const Frame frame(glm::normalize(light.center - x));
  const double one_minus_cos_max = sphere_cone_one_minus_cos(light.center, light.radius, x);
  const auto sample = [&](Vec2 u) {
    const Vec3 w = glm::normalize(sample_sphere_cone(light.center, light.radius, x, u).point - x);
    double phi = std::atan2(glm::dot(w, frame.bitangent), glm::dot(w, frame.tangent));
    if (phi < 0.0) phi += k_two_pi;
    const double cos_theta = glm::dot(w, frame.normal);
    return Vec2(2.0 * (cos_theta - (1.0 - one_minus_cos_max)) / one_minus_cos_max - 1.0,
                phi / k_pi - 1.0);
  };
  const auto density = [&](Vec2) {
    return pdf_solid_angle(light.center, light.radius, x) * k_pi * one_minus_cos_max / 2.0;
  };
  return square_sampler_p_value(sample, density, seed, k_cap_light_stream + 2,
                                "sphere cone (solid angle)");
}

/// The direct light of points above cornell-spheres' ceiling, where the light is seen beyond its
/// cap and a few units away: a strip of the left wall (rays from x = 1.5 going -x) and a strip
/// of the ceiling's top (rays from the same points going +x, slightly down, meeting it near
/// x = 72, 4 units under the light). n rays onto each at depth 1 (the strip's Le, 0, plus its
/// direct light), `estimate` against chapter 05's path tracer (uniform directions, another
/// seed): a z-test per strip from both sample variances, Sidak over the two.
template <class Estimate, class Reference>
double above_ceiling_direct_light_p_value(int n, std::uint64_t seed, Estimate&& estimate,
                                          Reference&& reference) {
  const Scene scene = make_cornell_spheres();
  std::vector<double> p_values;
  for (const Vec3 direction : {Vec3(-1, 0, 0), glm::normalize(Vec3(1, -0.02, 0))}) {
    double sum[2] = {0, 0}, sum2[2] = {0, 0};
    for (int k = 0; k < n; ++k)
      for (int which = 0; which < 2; ++which) {
        Rng rng(seed,
                stream_index((std::uint64_t{1} << 23) + which, static_cast<std::uint64_t>(k)));
        // y in [82, 84], z in [130, 160]: under the light (above y = 85.2 at z = 130 a point is
        // inside the light sphere, which no camera ray reaches)
        const Vec2 u = rng.uniform2();
        const Ray ray{{1.5, 82.0 + 2.0 * u.x, 130.0 + 30.0 * u.y}, direction};
        RayCount count;
        const Color l =
            which == 0 ? estimate(scene, ray, 1, rng, count) : reference(scene, ray, 1, rng, count);
        const double v = l.x + l.y + l.z;
        sum[which] += v;
        sum2[which] += v * v;
      }
    double mean[2], variance_of_mean[2];
    for (int i = 0; i < 2; ++i) {
      mean[i] = sum[i] / n;
      variance_of_mean[i] = (sum2[i] - sum[i] * mean[i]) / (n - 1.0) / n;
    }
    p_values.push_back(
        z_test_p_value(mean[0], mean[1], std::sqrt(variance_of_mean[0] + variance_of_mean[1])));
  }
  return sidak_p_value(p_values);
}

/// The light pdf per steradian integrates to 1 over the light's solid angle: from a point x
/// that sees the whole light, E over uniform hemisphere directions w of
/// [w reaches the light] p_w(w) / (1 / 2 pi) is 1. n directions; a z-test of the mean against 1.
/// `scene` holds the light alone; x's normal is `normal`.
inline double light_pdf_normalisation_p_value(const Scene& scene, const Vec3& x, const Vec3& normal,
                                              int n, std::uint64_t seed, std::uint64_t stream) {
  Rng rng(seed, stream);
  const Frame frame(normal);
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const Ray ray{x, frame.to_world(sample_uniform_hemisphere(rng.uniform2()))};
    double v = 0.0;
    if (const std::optional<Hit> hit = scene.closest_hit(ray))
      v = light_pdf_towards(scene, ray, *hit) / uniform_hemisphere_pdf();
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n, variance = (sum2 - sum * mean) / (n - 1.0);
  return z_test_p_value(mean, 1.0, std::sqrt(variance / n));
}

/// Two estimators of the same image, block by block: per pixel `samples` single-sample values
/// of each (estimator A on sample indices [0, samples), B on [2^20, 2^20 + samples)), the
/// difference of block means against its standard error (the sum of both variances of the
/// mean), a z-test per block and channel, Sidak over all (conservative for the correlated
/// channels, as in render/scene_quad_box_reference.hpp). Both estimate the same expectation when
/// both are unbiased for it.
template <class A, class B>
double block_agreement_p_value(const Scene& scene, int width, int height, int block, int samples,
                               std::uint64_t seed, A&& estimate_a, B&& estimate_b) {
  const Camera camera(scene.camera, width, height);
  const auto pixels = static_cast<std::size_t>(width * height);
  std::vector<ColorMoments> a(pixels), b(pixels);
  for (int s = 0; s < samples; ++s) {
    const auto first = static_cast<std::uint64_t>(s);
    const Image ia = render(camera, {1, first, seed, 1, nullptr}, estimate_a).image;
    const Image ib = render(camera, {1, first + (1u << 20), seed, 1, nullptr}, estimate_b).image;
    for (std::size_t p = 0; p < pixels; ++p) {
      a[p].add(ia.pixels[p]);
      b[p].add(ib.pixels[p]);
    }
  }
  std::vector<double> p_values;
  for (int by = 0; by < height; by += block)
    for (int bx = 0; bx < width; bx += block) {
      Vec3 d(0.0), variance(0.0);
      for (int y = by; y < std::min(height, by + block); ++y)
        for (int x = bx; x < std::min(width, bx + block); ++x) {
          const auto p = static_cast<std::size_t>(y * width + x);
          d += a[p].mean() - b[p].mean();
          const glm::dmat3 s = a[p].covariance_of_mean() + b[p].covariance_of_mean();
          variance += Vec3(s[0][0], s[1][1], s[2][2]);
        }
      for (int k = 0; k < 3; ++k)
        p_values.push_back(variance[k] > 0.0 ? z_test_p_value(d[k], 0.0, std::sqrt(variance[k]))
                                             : (d[k] == 0.0 ? 1.0 : 0.0));
    }
  return sidak_p_value(p_values);
}

/// A white floor (y = 0, facing up) under a one-sided lamp at y = 1 that faces UP, away from
/// it (black back): no light reaches the floor.
inline Scene lamp_facing_away_scene() {
  Scene scene;
  const auto white = scene.add_material({Color(0.8), Color(0.0)});
  const auto lamp = scene.add_material({Color(0.0), Color(10.0)});
  const auto back = scene.add_material({Color(0.0), Color(0.0)});
  scene.add_quad({{-50, 0, -50}, {0, 0, 100}, {100, 0, 0}, white});  // normal +y
  scene.add_quad({{-1, 1, -1}, {0, 0, 2}, {2, 0, 0}, lamp}, back);   // normal +y: faces away
  return scene;
}

/// Rays straight down onto the floor of lamp_facing_away_scene, depth 1: the exact answer is 0
/// (no spread). p = 1 if every sample is 0, else the z-test of the mean against 0 (0 when the
/// samples do not vary but are not 0).
template <class Estimate>
double light_behind_p_value(int n, std::uint64_t seed, Estimate&& estimate) {
  const Scene scene = lamp_facing_away_scene();
  double sum = 0.0, sum2 = 0.0;
  RayCount count;
  for (int k = 0; k < n; ++k) {
    Rng rng(seed, stream_index(std::uint64_t{1} << 22, static_cast<std::uint64_t>(k)));
    const Vec3 x(4.0 * rng.uniform() - 2.0, 0.0, 4.0 * rng.uniform() - 2.0);
    const Color l = estimate(scene, Ray{x + Vec3(0, 0.5, 0), Vec3(0, -1, 0)}, 1, rng, count);
    const double v = l.x + l.y + l.z;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / n, variance = std::max(0.0, (sum2 - sum * mean) / (n - 1.0));
  if (variance == 0.0) return mean == 0.0 ? 1.0 : 0.0;
  return z_test_p_value(mean, 0.0, std::sqrt(variance / n));
}

}  // namespace mcrt::testing
