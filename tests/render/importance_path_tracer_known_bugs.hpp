#pragma once
// Known-wrong importance-sampled path tracers, each chapter 07's loop with cosine-weighted
// directions and one mistake in the weight, kept so the tests can show the checks'
// procedures (render/importance_path_tracer_plates.hpp) reject them (tests/render/importance_path_tracer_test.cpp).
// The third classic mistake, cosine directions weighted as if uniform, is
// path_radiance_cosine_directions_uniform_pdf of render/path_tracer_known_bugs.hpp.
// Same signature as estimate_path_radiance.

#include "core/math.hpp"
#include "core/rng.hpp"
#include "render/path_tracer_known_bugs.hpp"
#include "render/scene.hpp"
#include "sampling/hemisphere.hpp"

namespace mcrt::testing {

/// Wrong: the cosine pdf written cos(theta) without its 1/pi: each bounce weighs a/pi, not a.
inline Color path_radiance_cosine_pdf_without_inv_pi(const Scene& scene, Ray ray, int max_depth,
                                                     Rng& rng, RayCount& count) {
  return path_radiance_with(scene, ray, max_depth, rng, count, sample_cosine_hemisphere,
                            [](Color f_r, Vec3 w) { return f_r * w.z / w.z; });
}

/// Wrong: f_r cos / p with the cosine divided out twice, f_r cos / (p cos): a / cos(theta).
inline Color path_radiance_dividing_by_cosine_twice(const Scene& scene, Ray ray, int max_depth,
                                                    Rng& rng, RayCount& count) {
  return path_radiance_with(scene, ray, max_depth, rng, count, sample_cosine_hemisphere,
                            [](Color f_r, Vec3 w) {
                              return f_r * w.z / (cosine_hemisphere_pdf(w.z) * w.z);
                            });
}

}  // namespace mcrt::testing
