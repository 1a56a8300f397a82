#pragma once
// Known-wrong splitting, each the path loop of common/render/splitting.hpp with one mistake,
// kept so the tests can show that the checks reject them (tests/render/splitting_test.cpp):
// the furnace mean z-test catches the first, the variance test the second, whose mean is
// right. Same signature as estimate_path_radiance_splitting.

#include <optional>

#include "core/rng.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "render/splitting.hpp"

namespace mcrt::testing {

/// The one mistake a wrong loop below makes.
enum class SplittingMistake {
  none,
  no_division,   ///< every branch carries the whole weight, not 1/n of it: n times the light
  one_direction  ///< the n branches share one direction: unbiased, but not 1/n of the variance
};

inline Color split_path_with(SplittingMistake mistake, const Scene& scene, Ray ray, Color beta,
                             int bounce, const Roulette& roulette, const Splitting& splitting,
                             Rng& rng, RayCount& count) {
  Color radiance(0.0);
  for (;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    const Material& material = scene.material(*hit);
    radiance += beta * material.emission;
    if (bounce >= roulette.min_depth) {
      const double q = survival_probability(roulette, beta);
      if (rng.uniform() >= q) break;
      beta /= q;
    }
    const Vec3 wo = -ray.direction;
    if (bounce < splitting.depth) {
      const Color share =
          mistake == SplittingMistake::no_division ? beta : beta / static_cast<double>(splitting.n);
      const Bounce shared = sample_bounce(material, *hit, wo, rng);
      for (int k = 0; k < splitting.n; ++k) {
        const Bounce next = mistake == SplittingMistake::one_direction
                                ? shared
                                : (k == 0 ? shared : sample_bounce(material, *hit, wo, rng));
        if (next.weight == Color(0.0)) continue;
        radiance += split_path_with(mistake, scene, next.ray, share * next.weight, bounce + 1,
                                    roulette, splitting, rng, count);
      }
      break;
    }
    const Bounce next = sample_bounce(material, *hit, wo, rng);
    beta *= next.weight;
    if (beta == Color(0.0)) break;
    ray = next.ray;
  }
  return radiance;
}

/// Each branch with the whole weight.
inline Color splitting_without_division(const Scene& scene, const Ray& ray,
                                        const Roulette& roulette, const Splitting& splitting,
                                        Rng& rng, RayCount& count) {
  return split_path_with(SplittingMistake::no_division, scene, ray, Color(1.0), 0, roulette,
                         splitting, rng, count);
}

/// The branches reuse one direction.
inline Color splitting_one_direction(const Scene& scene, const Ray& ray, const Roulette& roulette,
                                     const Splitting& splitting, Rng& rng, RayCount& count) {
  return split_path_with(SplittingMistake::one_direction, scene, ray, Color(1.0), 0, roulette,
                         splitting, rng, count);
}

}  // namespace mcrt::testing
