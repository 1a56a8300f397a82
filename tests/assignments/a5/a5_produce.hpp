#pragma once
// What a5's checks ask of the three estimators, produced in bulk. An A5Estimator names one
// estimator and its parameters as plain numbers (so it travels in a request); A5Producer runs
// it with the functions it holds: the student's (LocalSubject), or a known-wrong one in place of
// one of them (diagnosis_test.cpp). No test and no verdict here: the subject program includes it.
//   a5.1 roulette(scene, ray, roulette, rng, count)          estimate_path_radiance_roulette
//   a5.2 importance(scene, ray, max_depth, pdf, rng, count)  estimate_importance_path_radiance
//   a5.3 nee(scene, ray, path_end, rng, count)               estimate_nee_radiance

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "assignments/a4/a4_produce.hpp"
#include "assignments/subject/requests.hpp"
#include "render/importance_path_tracer.hpp"
#include "render/next_event_estimation.hpp"
#include "render/russian_roulette.hpp"
#include "render/scene.hpp"
#include "sampling/cosine_power.hpp"

namespace mcrt::testing::assignment {

/// NEE at depth k without roulette (the path tracer's truncation).
inline PathEnd nee_depth_cut(int k) {
  PathEnd end;
  end.roulette.min_depth = 1 << 20;  // never reached: no roulette
  end.max_depth = k;
  return end;
}

inline A5Estimator roulette_estimator(const Roulette& r) {
  return {A5Estimator::roulette, r.min_depth, static_cast<int>(r.policy), r.q, r.floor, -1, 0, 0};
}

inline A5Estimator importance_estimator(int max_depth, const HemispherePdf& pdf) {
  return {A5Estimator::importance, 0, 0, 0.0, 0.0, max_depth, static_cast<int>(pdf.kind), pdf.m};
}

inline A5Estimator nee_estimator(const PathEnd& end) {
  return {A5Estimator::nee,
          end.roulette.min_depth,
          static_cast<int>(end.roulette.policy),
          end.roulette.q,
          end.roulette.floor,
          end.max_depth,
          0,
          0};
}

inline Roulette roulette_of(const A5Estimator& e) {
  return {e.min_depth, static_cast<RoulettePolicy>(e.policy), e.q, e.floor};
}

/// n furnace paths (path i in a uniformly random direction, stream (block, i) of seed) of
/// `estimate(scene, ray, rng, count)`: their radiance and rays.
template <class Estimate>
std::vector<FurnacePath> a5_furnace_paths(const Scene& furnace, int n, std::uint64_t seed,
                                          std::uint64_t block, Estimate&& estimate) {
  std::vector<FurnacePath> paths(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    Rng rng(seed, stream_index(block, static_cast<std::uint64_t>(i)));
    const Ray ray{Vec3(0.0), sample_uniform_sphere(rng.uniform2())};
    RayCount count;
    paths[static_cast<std::size_t>(i)] = {average(estimate(furnace, ray, rng, count)), count.rays};
  }
  return paths;
}

template <class RouletteFn, class ImportanceFn, class NeeFn>
struct A5Producer {
  RouletteFn roulette;
  ImportanceFn importance;
  NeeFn nee;

  Color run(const A5Estimator& e, const Scene& scene, const Ray& ray, Rng& rng,
            RayCount& count) const {
    switch (e.kind) {
      case A5Estimator::roulette: return roulette(scene, ray, roulette_of(e), rng, count);
      case A5Estimator::importance:
        return importance(scene, ray, e.max_depth,
                          HemispherePdf{static_cast<HemispherePdf::Kind>(e.pdf_kind), e.pdf_m}, rng,
                          count);
      case A5Estimator::nee: {
        PathEnd end;
        end.roulette = roulette_of(e);
        end.max_depth = e.max_depth;
        return nee(scene, ray, end, rng, count);
      }
    }
    throw std::invalid_argument("unknown a5 estimator");
  }

  /// n paths in the furnace (albedo, Le = 1): a5_furnace_paths.
  std::vector<FurnacePath> a5_paths(const A5Estimator& e, double albedo, int n, std::uint64_t seed,
                                    std::uint64_t block) const {
    return a5_furnace_paths(make_furnace(albedo, 1.0), n, seed, block,
                            [&](const Scene& s, const Ray& r, Rng& rng, RayCount& c) {
                              return run(e, s, r, rng, c);
                            });
  }

  /// One furnace path from the centre along `direction`, from Rng(seed, stream).
  PathSample a5_single(const A5Estimator& e, double albedo, double emission, Vec3 direction,
                       std::uint64_t seed, std::uint64_t stream) const {
    const Scene furnace = make_furnace(albedo, emission);
    Rng rng(seed, stream);
    RayCount count;
    const double L = average(run(e, furnace, {Vec3(0.0), direction}, rng, count));
    return {L, count.rays};
  }

  /// Every sample of the Cornell box (its lamp at 3x its area, in `lamp_parts` strips) at
  /// size x size pixels, spp per pixel, in region_stats's order.
  std::vector<double> a5_regions(const A5Estimator& e, int lamp_parts, int size, int spp,
                                 std::uint64_t seed) const {
    return every_pixel_sample(make_cornell_box(3.0, lamp_parts), size, spp, seed,
                              [&](const Scene& scene, const Ray& ray, Rng& rng, RayCount& count) {
                                return run(e, scene, ray, rng, count);
                              });
  }

  /// n rays onto cornell-spheres' left wall between the ceiling and the light (y in [82, 84],
  /// z in [130, 160]: under the light), sample i from the stream (70, i) of seed.
  std::vector<double> a5_wall(const A5Estimator& e, int n, std::uint64_t seed) const {
    const Scene scene = make_cornell_spheres();
    std::vector<double> values;
    for (int i = 0; i < n; ++i) {
      Rng rng(seed, stream_index(70, static_cast<std::uint64_t>(i)));
      const Vec2 u = rng.uniform2();
      const Ray ray{{1.5, 82.0 + 2.0 * u.x, 130.0 + 30.0 * u.y}, {-1.0, 0.0, 0.0}};
      RayCount count;
      values.push_back(average(run(e, scene, ray, rng, count)));
    }
    return values;
  }
};

template <class R, class I, class N>
A5Producer<R, I, N> a5_producer(R roulette, I importance, N nee) {
  return {roulette, importance, nee};
}

}  // namespace mcrt::testing::assignment
