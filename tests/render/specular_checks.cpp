// Statistical checks of the estimators on smallpt's own scene, mirror and glass included,
// against the independent renderer of render/scene_sphere_box_reference.hpp (smallpt's glass
// written as smallpt writes it, its branch chosen with smallpt's probability, not with R).
//
// Each check compares the two renders of a 32 x 24 image, 2000 samples per pixel each, region
// by region: every 4 x 4 block, every row (the top row and the bottom one included), every
// column and the border ring, each channel a two-sided z-test, Sidak over all of them, so the
// family-wise false-failure rate is at most alpha = 1e-4 (support/region_comparison.hpp).
// Chapter 05's and 07's path tracers cut at depth 64: the light of longer paths (a factor
// below 0.75 per diffuse bounce) is under 1e-7 of the image, far below any region's standard
// error; NEE and MIS end their paths by roulette alone, unbiased like the reference.

#include <cstdint>

#include "render/importance_path_tracer.hpp"
#include "render/mis.hpp"
#include "render/next_event_estimation.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"
#include "render/scene_sphere_box_reference.hpp"
#include "sampling/cosine_power.hpp"
#include "stats/check.hpp"

using namespace mcrt;

namespace {

constexpr int k_cut = 64;

template <class Estimate>
double smallpt_check(std::uint64_t seed, Estimate&& estimate) {
  return mcrt::testing::sphere_box_comparison(make_smallpt(), {32, 24, 4, 2000}, seed, estimate)
      .p_value;
}

MCRT_STATISTICAL_CHECK_AT_MOST(path_tracer_agrees_with_independent_renderer_smallpt, 1e-4) {
  return smallpt_check(seed, [](const Scene& s, const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_path_radiance(s, ray, k_cut, rng, count);
  });
}

MCRT_STATISTICAL_CHECK_AT_MOST(cosine_path_tracer_agrees_with_independent_renderer_smallpt, 1e-4) {
  return smallpt_check(seed, [](const Scene& s, const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_importance_path_radiance(s, ray, k_cut, cosine_power_pdf(1), rng, count);
  });
}

MCRT_STATISTICAL_CHECK_AT_MOST(nee_agrees_with_independent_renderer_smallpt, 1e-4) {
  return smallpt_check(seed, [](const Scene& s, const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_nee_radiance(s, ray, PathEnd{Roulette{}, -1}, rng, count);
  });
}

MCRT_STATISTICAL_CHECK_AT_MOST(mis_agrees_with_independent_renderer_smallpt, 1e-4) {
  return smallpt_check(seed, [](const Scene& s, const Ray& ray, Rng& rng, RayCount& count) {
    return estimate_mis_radiance(s, ray, PathEnd{Roulette{}, -1}, MisHeuristic::power, rng, count);
  });
}

}  // namespace
