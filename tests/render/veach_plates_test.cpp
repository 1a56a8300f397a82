// Veach's plates as a built-in scene (make_scene("veach-plates"), render/scene.hpp): built from
// make_veach_plates() (render/veach_plates.hpp), so the two cannot differ; open, so rays leave
// it with nothing; and seen through Material::f_r by chapters 05 and 07's path tracers, whose
// direct light (depth 1) agrees with chapter 08's own glossy estimator (render/glossy_direct.hpp),
// an independent piece of code over the same plates, with a wrong weight caught.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "core/rng.hpp"
#include "integration/statistics.hpp"
#include "render/glossy_direct.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/mis.hpp"
#include "render/next_event_estimation.hpp"
#include "render/path_tracer.hpp"
#include "render/render.hpp"
#include "render/scene.hpp"
#include "render/veach_plates.hpp"
#include "sampling/cosine_power.hpp"
#include "sampling/sampling.hpp"
#include "stats/hypothesis.hpp"

using namespace mcrt;
using namespace mcrt::testing;

namespace {

constexpr double k_alpha = 1e-4;  // the suite's false-failure rate, family-wise per test

TEST(VeachPlatesSceneTest, IsMakeVeachPlatesAsAScene) {
  const VeachPlates plates = make_veach_plates();
  const Scene scene = make_scene("veach-plates");
  EXPECT_EQ(scene.name, "veach-plates");
  ASSERT_EQ(scene.quads().size(), plates.plate_count());
  ASSERT_EQ(scene.spheres().size(), plates.light_count());
  for (std::size_t k = 0; k < plates.plate_count(); ++k) {
    const Quad& q = scene.quads()[k];
    EXPECT_EQ(q.corner(), plates.plates[k].corner());
    EXPECT_EQ(q.edge_u(), plates.plates[k].edge_u());
    EXPECT_EQ(q.edge_v(), plates.plates[k].edge_v());
    const Material& m = scene.materials[q.material()];
    EXPECT_EQ(m.albedo, Color(plates.materials[k].rho_d));
    EXPECT_EQ(m.specular, plates.materials[k].rho_s);
    EXPECT_EQ(m.exponent, plates.materials[k].m);
    EXPECT_TRUE(m.has_lobe());
    EXPECT_FALSE(m.is_emitter());
  }
  for (std::size_t j = 0; j < plates.light_count(); ++j) {
    const Sphere& s = scene.spheres()[j];
    EXPECT_EQ(s.center, plates.lights[j].center);
    EXPECT_EQ(s.radius, plates.lights[j].radius);
    EXPECT_EQ(scene.materials[s.material].emission, Color(plates.radiance[j]));
    EXPECT_FALSE(scene.materials[s.material].has_lobe());
  }
  EXPECT_EQ(scene.emitters().size(), plates.light_count());
  EXPECT_EQ(scene.camera.eye, plates.camera.eye);
  EXPECT_EQ(scene.camera.direction, plates.camera.direction);
  EXPECT_EQ(scene.camera.vertical_fov, plates.camera.vertical_fov);
  // The same hits, materials included, for every pixel's ray: the numbering is shared.
  const Camera camera(scene.camera, 64, 48);
  int plate_hits = 0, light_hits = 0, misses = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      const Ray ray = camera.generate_ray(x, y, {0.5, 0.5});
      const std::optional<Hit> a = scene.closest_hit(ray), b = closest_hit(plates, ray);
      ASSERT_EQ(a.has_value(), b.has_value()) << x << " " << y;
      if (!a) {
        ++misses;
        continue;
      }
      EXPECT_EQ(a->material, b->material) << x << " " << y;
      EXPECT_EQ(a->point, b->point) << x << " " << y;
      (plates.is_light(*a) ? light_hits : plate_hits) += 1;
    }
  EXPECT_GT(plate_hits, 200);  // the plates fill a good part of the view ...
  EXPECT_GT(light_hits, 0);    // ... the lights show ...
  EXPECT_GT(misses, 200);      // ... and much of it is the empty background
}

// The scene is open: a path that leaves it ends with what it has gathered, one ray each.
TEST(VeachPlatesSceneTest, RaysThatLeaveTheSceneCarryNothing) {
  const Scene scene = make_scene("veach-plates");
  const Ray up{scene.camera.eye, {0.0, 1.0, 0.0}};
  EXPECT_FALSE(scene.closest_hit(up).has_value());
  Rng rng(1, 0);
  RayCount count;
  EXPECT_EQ(estimate_path_radiance(scene, up, 10, rng, count), Color(0.0));
  EXPECT_EQ(count.rays, 1u);
}

// One pixel's estimator along a fixed camera ray: the radiance of one path (or sample).
using RayEstimate = std::function<Color(const Ray&, Rng&, RayCount&)>;

// n estimates along `ray`, estimate i from stream i of `seed`: their mean and standard error,
// and how many were not 0.
struct RaySamples {
  RunningStats stats;
  int nonzero = 0;
};
RaySamples sample_ray(const RayEstimate& estimate, const Ray& ray, int n, std::uint64_t seed) {
  RaySamples s;
  RayCount count;
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, static_cast<std::uint64_t>(i));
    const double y = average(estimate(ray, rng, count));
    s.nonzero += y != 0.0;
    s.stats.add(y);
  }
  return s;
}

// The camera ray through the point of plate k where light j's centre shows in its mirror.
Ray ray_to_highlight(const VeachPlates& plates, std::size_t plate, std::size_t light) {
  const Vec3 eye = plates.camera.eye;
  return {eye, glm::normalize(mirror_highlight(plates, plate, light) - eye)};
}

// A path tracer that forgot the lobe: the bounce weighted by the diffuse part alone
// (Material::brdf(), rho / pi), as the chapters were before glossy materials. Depth 1.
Color estimate_without_lobe(const Scene& scene, Ray ray, Rng& rng, RayCount& count) {
  Color radiance(0.0), beta(1.0);
  for (int bounce = 0;; ++bounce) {
    ++count.rays;
    const std::optional<Hit> hit = scene.closest_hit(ray);
    if (!hit) break;
    radiance += beta * scene.material(*hit).emission;
    if (bounce == 1) break;
    const Vec3 local = sample_uniform_hemisphere(rng.uniform2());
    beta *= scene.material(*hit).brdf() * local.z / uniform_hemisphere_pdf();
    ray = spawn_ray(*hit, Frame(hit->normal).to_world(local));
  }
  return radiance;
}

// Depth 1 is the camera ray's hit and one bounce: at a plate, the direct light it reflects,
// which render/glossy_direct.hpp estimates by its own code over make_veach_plates() (MIS, power
// heuristic: light sampling of the spheres' cones and Phong-lobe sampling). Chapter 05's
// uniform and chapter 07's cosine path tracers, seeing the lobe through Material::f_r, must
// agree with it, and so must chapter 08's NEE and MIS path estimators (render/mis.hpp, which
// renders chapter 05's reference) cut at depth 1: two-sample z-tests at three highlights,
// Sidak-combined, false-failure rate k_alpha for the whole test.
//
// The cells are those where a hemisphere pdf finds the light often enough for its mean to be
// normal at the tail tested (z ~ 4.5): plate 1 (m = 100) at light 3's highlight, plate 2
// (m = 1000) at lights 3 and 2's. There every light the lobe (about 1/sqrt(m) rad wide) reaches
// is met by ~5e-4 of uniform directions or more: >= 450 paths of 10^6 carry its light
// (Poisson skewness <= 0.05). Elsewhere a light 0.2 rad off the lobe's axis (the next one in
// the row), or the smallest light (3e-5 sr), adds 10 % or more of the light through tens of
// rare bright paths, and on the sharpest plate the lobe is hit too rarely: a z-test there
// rejects more often than stated, so those cells are left out. Measured over 40 runs of other
// seeds: 5.2 % of the 480 p-values below 0.05 and 1.7 % below 0.01 with these cells (8.1 % and
// 1.9 % with plate 1 at light 2 in place of plate 2 at light 2).
TEST(VeachPlatesSceneTest, DepthOneEstimatorsMatchGlossyDirect) {
  const VeachPlates plates = make_veach_plates();
  const Scene scene = make_scene("veach-plates");
  const HemispherePdf cosine = cosine_power_pdf(1);
  constexpr int k_paths = 1000000;       // per cell and path tracer: ~0.15 s each
  constexpr int k_mis_samples = 100000;  // MIS's error is 5-40x smaller per sample
  const RayEstimate uniform = [&](const Ray& r, Rng& rng, RayCount& c) {
    return estimate_path_radiance(scene, r, 1, rng, c);
  };
  const RayEstimate cosine_tracer = [&](const Ray& r, Rng& rng, RayCount& c) {
    return estimate_importance_path_radiance(scene, r, 1, cosine, rng, c);
  };
  const RayEstimate without_lobe = [&](const Ray& r, Rng& rng, RayCount& c) {
    return estimate_without_lobe(scene, r, rng, c);
  };
  // Chapter 08's path estimators, which render chapter 05's reference: at depth 1 their light
  // sample (and MIS's cosine sample that meets a light) is the direct light too.
  const PathEnd depth_one{Roulette{}, 1};
  const RayEstimate nee = [&](const Ray& r, Rng& rng, RayCount& c) {
    return estimate_nee_radiance(scene, r, depth_one, rng, c);
  };
  const RayEstimate mis_path = [&](const Ray& r, Rng& rng, RayCount& c) {
    return estimate_mis_radiance(scene, r, depth_one, MisHeuristic::power, rng, c);
  };
  std::vector<double> p_values, p_values_without_lobe;
  for (const auto& [plate, light] : {std::pair{1, 3}, std::pair{2, 3}, std::pair{2, 2}}) {
    const Ray ray = ray_to_highlight(plates, plate, light);
    const std::optional<Hit> hit = scene.closest_hit(ray);
    ASSERT_TRUE(hit && hit->material == static_cast<std::uint32_t>(plate));  // on its plate
    const RaySamples mis = sample_ray(
        [&](const Ray& r, Rng& rng, RayCount& c) {
          return estimate_plates_radiance(plates, r, GlossyStrategy::mis_power, rng, c);
        },
        ray, k_mis_samples, 3);
    ASSERT_GT(mis.stats.mean(), 0.1);  // a lit highlight
    const auto agreement = [&](const RayEstimate& estimate, std::uint64_t seed, int n) {
      const RaySamples s = sample_ray(estimate, ray, n, seed);
      const double se = std::hypot(s.stats.standard_error(), mis.stats.standard_error());
      return z_test_p_value(s.stats.mean() - mis.stats.mean(), 0.0, se);
    };
    p_values.push_back(agreement(uniform, 4, k_paths));
    p_values.push_back(agreement(cosine_tracer, 5, k_paths));
    p_values.push_back(agreement(nee, 7, k_mis_samples));
    p_values.push_back(agreement(mis_path, 8, k_mis_samples));
    p_values_without_lobe.push_back(agreement(without_lobe, 6, k_paths));
  }
  EXPECT_GT(sidak_p_value(p_values), k_alpha);
  // The test can fail: the diffuse-only weight leaves the plates black, and is rejected.
  EXPECT_LT(sidak_p_value(p_values_without_lobe), k_alpha);
}

}  // namespace
