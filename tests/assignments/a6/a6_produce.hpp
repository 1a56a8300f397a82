#pragma once
// What a6's checks ask of the glossy lobe, the heuristics and the MIS estimator, produced in
// bulk. LocalSubject answers a6's requests with these (the student's functions); the checks run
// known-wrong variants through them (diagnosis_test.cpp). No test and no verdict here: the
// subject program includes it.
//   a6.1 sample_phong_lobe_local(u, m), phong_lobe_pdf(wi, reflected, m)
//   a6.2 balance_heuristic(p_s, p_o), power_heuristic(p_s, p_o)
//   a6.3 estimate_mis(scene, hit, wo, heuristic, rng, count) (and draw_light_sample in it)
//   a6.4 sample_dielectric(material, wo, n, entering, u)

#include <cstdint>
#include <optional>
#include <vector>

#include "assignments/subject/requests.hpp"
#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/glossy_direct.hpp"
#include "render/material.hpp"
#include "render/mis.hpp"
#include "render/specular.hpp"
#include "render/veach_plates.hpp"

namespace mcrt::testing::assignment {

/// One camera sample of the plates: the light's Le if the camera ray meets one, else what
/// `reflected(hit, wo, rng, count)` estimates at the plate point (0 on the background).
template <class Reflected>
double plates_sample(const VeachPlates& scene, const Ray& ray, Rng& rng, RayCount& count,
                     Reflected&& reflected) {
  ++count.rays;
  const std::optional<Hit> hit = closest_hit(scene, ray);
  if (!hit) return 0.0;
  if (scene.is_light(*hit)) return scene.radiance[scene.light_index(*hit)];
  return reflected(*hit, -ray.direction, rng, count);
}

/// Every camera sample of the 16 plate x light regions (plate_regions) of a width x height
/// render: region by region, rows, pixels, then spp samples, sample s of pixel p on the stream
/// (p, s) of `seed`.
template <class Reflected>
std::vector<double> plates_region_samples(int width, int height, int spp, std::uint64_t seed,
                                          Reflected&& reflected) {
  const VeachPlates scene = make_veach_plates();
  const Camera camera(scene.camera, width, height);
  std::vector<double> values;
  RayCount count;
  for (const PlateRegion& r : plate_regions(scene, width, height))
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x)
        for (int s = 0; s < spp; ++s) {
          Rng rng(seed, stream_index(static_cast<std::uint64_t>(y * width + x),
                                     static_cast<std::uint64_t>(s)));
          const Ray ray = camera.generate_ray(x, y, rng.uniform2());
          values.push_back(plates_sample(scene, ray, rng, count, reflected));
        }
  return values;
}

/// The region samples of `strategy` with `mis(scene, hit, wo, heuristic, rng, count)` as MIS:
/// light or BSDF sampling average two samples, MIS takes one of each (two rays either way).
template <class Mis>
std::vector<double> a6_region_samples(Mis&& mis, A6Strategy strategy, int width, int height,
                                      int spp, std::uint64_t seed) {
  const VeachPlates scene = make_veach_plates();
  return plates_region_samples(
      width, height, spp, seed, [&](const Hit& hit, const Vec3& wo, Rng& rng, RayCount& count) {
        switch (strategy) {
          case A6Strategy::light: {
            const double a = estimate_light_sampling(scene, hit, wo, rng, count);
            return 0.5 * (a + estimate_light_sampling(scene, hit, wo, rng, count));
          }
          case A6Strategy::bsdf: {
            const double a = estimate_bsdf_sampling(scene, hit, wo, rng, count);
            return 0.5 * (a + estimate_bsdf_sampling(scene, hit, wo, rng, count));
          }
          case A6Strategy::mis_balance:
            return mis(scene, hit, wo, MisHeuristic::balance, rng, count);
          case A6Strategy::mis_power: break;
        }
        return mis(scene, hit, wo, MisHeuristic::power, rng, count);
      });
}

/// The glass a6.4 is graded on: index `ior` inside, air outside, tint 1, the exact Fresnel
/// equations (so every weight is exactly 1, and the reflected fraction is R).
inline Material a6_glass(double ior) {
  Material glass;
  glass.delta = Delta::dielectric;
  glass.ior = ior;
  return glass;
}

/// `sample(material, wo, n, entering, u)` (sample_dielectric or a known-wrong one) at each query.
template <class Sample>
std::vector<DielectricAnswer> dielectric_answers(Sample&& sample, double ior,
                                                 const std::vector<DielectricQuery>& queries) {
  const Material glass = a6_glass(ior);
  std::vector<DielectricAnswer> out;
  out.reserve(queries.size());
  for (const DielectricQuery& q : queries) {
    const BsdfSample s = sample(glass, q.wo, q.n, q.entering, q.u);
    out.push_back({s.wi, Vec3(s.weight), s.transmitted});
  }
  return out;
}

}  // namespace mcrt::testing::assignment
