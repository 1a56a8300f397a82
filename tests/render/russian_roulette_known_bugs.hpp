#pragma once
// Known-wrong Russian roulette, each chapter 06's path loop (common/render/russian_roulette.hpp)
// with one mistake, kept so the tests can show that the checks reject them
// (tests/render/russian_roulette_test.cpp): the furnace mean z-test catches the first three, the
// path-length chi-square the fourth, whose mean is right. Same signature as
// estimate_path_radiance_roulette.

#include <algorithm>
#include <optional>

#include "core/math.hpp"
#include "core/rng.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "sampling/frame.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt::testing {

/// The one mistake a wrong loop below makes.
enum class RouletteMistake { none, no_division, before_emission, q_not_clamped, from_depth_zero };

/// The roulette path loop with `mistake` in it: the shell every wrong variant below fills.
inline Color roulette_path_with(RouletteMistake mistake, const Scene& scene, Ray ray,
                                const Roulette& roulette, Rng& rng, RayCount& count) {
  const int min_depth = mistake == RouletteMistake::from_depth_zero ? 0 : roulette.min_depth;
  const auto q_of = [&](const Color& beta) {
    if (mistake != RouletteMistake::q_not_clamped || roulette.policy == RoulettePolicy::fixed)
      return survival_probability(roulette, beta);
    return std::max({beta.r, beta.g, beta.b, roulette.floor});
  };
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    const bool roulette_here = bounce >= min_depth;
    const double q = roulette_here ? q_of(beta) : 1.0;
    if (mistake == RouletteMistake::before_emission && roulette_here && rng.uniform() >= q) break;
    radiance += beta * material.emission;
    if (roulette_here) {
      if (mistake != RouletteMistake::before_emission && rng.uniform() >= q) break;
      if (mistake != RouletteMistake::no_division) beta /= q;
    }
    const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
    beta *= material.brdf() * local.z / uniform_hemisphere_pdf();
    if (beta == Color(0.0)) break;
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

/// Wrong: the survivors' weight is not divided by q, so every term past d loses a factor q^m.
inline Color roulette_without_division(const Scene& scene, Ray ray, const Roulette& roulette,
                                       Rng& rng, RayCount& count) {
  return roulette_path_with(RouletteMistake::no_division, scene, ray, roulette, rng, count);
}

/// Wrong: roulette runs before the hit's emission is added, so a path stopped at x_j loses Le(x_j).
inline Color roulette_before_emission(const Scene& scene, Ray ray, const Roulette& roulette,
                                      Rng& rng, RayCount& count) {
  return roulette_path_with(RouletteMistake::before_emission, scene, ray, roulette, rng, count);
}

/// Wrong: the throughput q is not clamped to 1, so a weight above 1 is divided by it unpaid.
inline Color roulette_q_not_clamped(const Scene& scene, Ray ray, const Roulette& roulette, Rng& rng,
                                    RayCount& count) {
  return roulette_path_with(RouletteMistake::q_not_clamped, scene, ray, roulette, rng, count);
}

/// Wrong: roulette from vertex 0, whatever min_depth asks: unbiased, but paths are too short.
inline Color roulette_from_depth_zero(const Scene& scene, Ray ray, const Roulette& roulette,
                                      Rng& rng, RayCount& count) {
  return roulette_path_with(RouletteMistake::from_depth_zero, scene, ray, roulette, rng, count);
}

}  // namespace mcrt::testing
