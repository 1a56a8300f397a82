#pragma once
// Known-wrong recursive estimators for the assignment a3 grader's diagnoses
// (tests/assignments/diagnosis_test.cpp). Same signature as incident_radiance.

#include <optional>

#include "core/rng.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt::testing {

/// The recursion of incident_radiance stopping at depth max_depth + stop_shift, its N branches
/// sharing one direction when `shared_direction`, its sum divided by N when `divide_by_n`.
inline Color incident_radiance_with(const Scene& scene, const Ray& ray, int depth,
                                    const RecursiveSettings& s, Rng& rng, RayCount& count,
                                    int stop_shift, bool shared_direction, bool divide_by_n) {
  ++count.rays;
  const std::optional<Hit> p = scene.closest_hit(ray);
  if (!p) return Color(0.0);
  const Material& material = scene.material(*p);
  Color L = material.emission;
  if (depth >= s.max_depth + stop_shift) return L;
  const Frame frame(p->normal);
  const Vec2 first_u = rng.uniform2();
  for (int i = 0; i < s.branching; ++i) {
    const Vec3 wi = frame.to_world(
        sample_uniform_hemisphere(shared_direction || i == 0 ? first_u : rng.uniform2()));
    const double cos_theta_i = glm::dot(wi, p->normal);
    const Color L_i = incident_radiance_with(scene, spawn_ray(*p, wi), depth + 1, s, rng, count,
                                             stop_shift, shared_direction, divide_by_n);
    L += L_i * material.brdf() * cos_theta_i /
         (uniform_hemisphere_pdf() * (divide_by_n ? s.branching : 1));
  }
  return L;
}

/// Wrong: the recursion stops one bounce late (depth == k + 1): N^(k+1) rays too many.
inline Color incident_radiance_one_bounce_late(const Scene& scene, const Ray& ray, int depth,
                                               const RecursiveSettings& s, Rng& rng,
                                               RayCount& count) {
  return incident_radiance_with(scene, ray, depth, s, rng, count, 1, false, true);
}

/// Wrong: the recursion stops one bounce early (depth == k - 1): N^k rays too few.
inline Color incident_radiance_one_bounce_early(const Scene& scene, const Ray& ray, int depth,
                                                const RecursiveSettings& s, Rng& rng,
                                                RayCount& count) {
  return incident_radiance_with(scene, ray, depth, s, rng, count, -1, false, true);
}

/// Wrong: the N branches' sum is not divided by N: each level weighs N a instead of a.
inline Color incident_radiance_without_one_over_n(const Scene& scene, const Ray& ray, int depth,
                                                  const RecursiveSettings& s, Rng& rng,
                                                  RayCount& count) {
  return incident_radiance_with(scene, ray, depth, s, rng, count, 0, false, false);
}

/// Wrong: the N branches reuse one direction: the right mean, the variance of N = 1.
inline Color incident_radiance_one_shared_direction(const Scene& scene, const Ray& ray, int depth,
                                                    const RecursiveSettings& s, Rng& rng,
                                                    RayCount& count) {
  return incident_radiance_with(scene, ray, depth, s, rng, count, 0, true, true);
}

}  // namespace mcrt::testing
