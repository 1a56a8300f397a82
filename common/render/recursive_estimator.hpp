#pragma once
/// The lecture's recursive estimator of the rendering equation: at every hit, N new directions,
/// each followed recursively, until a fixed depth k. After k bounces it has traced up to N^k
/// rays for the last bounce alone; chapter 04 measures that explosion.
///
///   incidentRadiance(x, w):
///     p = intersectScene(x, w)
///     L = p.emittedLight(-w)
///     for i = 1..N:
///       wi = sampleDirection(p.normal)          // uniform on the hemisphere, pdf 1/(2 pi)
///       L += incidentRadiance(p, wi) * p.BRDF(wi, -w) * cos_theta_i * 2 pi / N
///     return L

#include <cstdint>
#include <limits>
#include <optional>

#include "core/rng.hpp"
#include "geometry/hit.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "sampling/sampling.hpp"

namespace mcrt {

/// The two knobs of the recursion.
struct RecursiveSettings {
  int branching = 1;  ///< N: directions sampled at every hit
  int max_depth = 0;  ///< k: bounces after which the recursion returns emitted light only
};

/// Radiance arriving along `ray` (at its origin, from direction -ray.direction), estimated by
/// the recursion above; `depth` is the number of bounces already taken (0 for a camera ray).
/// Every closest-hit query adds one to `count`. A ray that leaves the scene brings no light.
///
/// Expectation: the Neumann series of the rendering equation cut after k bounces,
///   E[L_k] = Le + T Le + ... + T^k Le     (T: the transport operator, one bounce),
/// so light that needs more than k bounces is missing. In the furnace (emission Le and albedo
/// a everywhere) each branch's weight w = f_r cos / pdf = (a/pi) cos * 2 pi = 2 a cos(theta)
/// has E[w] = a and E[w^2] = 4 a^2 / 3 (cos(theta) is uniform on [0,1]), so for every N
///   m_k = E[L_k] = Le (1 + a + ... + a^k),
///   V_k = Var[L_k] = a^2 / (3 N) * (4 V_(k-1) + m_(k-1)^2),   V_0 = 0
/// (L_k = Le + (1/N) sum_i w_i L_(k-1),i with independent terms; Var[w L] = E[w^2] E[L^2] -
/// (E[w] E[L])^2). Branching divides the variance by N per level, at N times the rays.
inline Color incident_radiance(const Scene& scene, const Ray& ray, int depth,
                               const RecursiveSettings& settings, Rng& rng, RayCount& count) {
  // ASSIGNMENT a3.1 BEGIN needs=a2.1 stub: (void)scene; (void)ray; (void)depth; (void)settings; (void)rng; (void)count; NOT_IMPLEMENTED(incident_radiance);
  ++count.rays;
  const std::optional<Hit> p = scene.closest_hit(ray);  // p = intersectScene(x, w)
  if (!p) return Color(0.0);                            // the ray left the scene
  const Material& material = scene.material(*p);
  Color L = material.emission;                // L = p.emittedLight(-w)
  if (depth == settings.max_depth) return L;  // the lecture's missing stopping rule
  const Frame frame(p->normal);
  const int N = settings.branching;
  for (int i = 0; i < N; ++i) {
    const Vec3 wi = frame.to_world(sample_uniform_hemisphere(rng.uniform2()));
    const double cos_theta_i = glm::dot(wi, p->normal);
    const Color L_i = incident_radiance(scene, spawn_ray(*p, wi), depth + 1, settings, rng, count);
    L += L_i * material.brdf() * cos_theta_i / (uniform_hemisphere_pdf() * N);
  }
  return L;
  // ASSIGNMENT a3.1 END
}

/// The rays one camera sample traces when no path escapes (the furnace):
///   1 + N + N^2 + ... + N^k = (N^(k+1) - 1) / (N - 1),   k + 1 for N = 1.
/// Saturates at the largest std::uint64_t instead of overflowing.
inline std::uint64_t max_rays_per_sample(int branching, int max_depth) {
  // ASSIGNMENT a3.2 BEGIN stub: (void)branching; (void)max_depth; NOT_IMPLEMENTED(max_rays_per_sample);
  constexpr std::uint64_t k_max = std::numeric_limits<std::uint64_t>::max();
  const auto n = static_cast<std::uint64_t>(branching);
  std::uint64_t total = 0, level = 1;  // level = N^j, the rays at depth j
  for (int j = 0; j <= max_depth; ++j) {
    if (total > k_max - level) return k_max;
    total += level;
    if (j < max_depth && n > 1 && level > k_max / n) return k_max;
    level *= n;
  }
  return total;
  // ASSIGNMENT a3.2 END
}

/// The furnace's closed forms above: E[L_k] / Le and Var[L_k] / Le^2 (scalar: grey albedo a).
struct FurnaceMoments {
  double mean = 0.0;
  double variance = 0.0;
};
inline FurnaceMoments furnace_moments(double albedo, int branching, int max_depth) {
  FurnaceMoments m{1.0, 0.0};  // k = 0: L = Le exactly
  for (int k = 1; k <= max_depth; ++k) {
    const double variance =
        albedo * albedo / (3.0 * branching) * (4.0 * m.variance + m.mean * m.mean);
    m.mean = 1.0 + albedo * m.mean;
    m.variance = variance;
  }
  return m;
}

}  // namespace mcrt
