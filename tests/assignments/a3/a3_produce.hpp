#pragma once
// What a3's checks ask of the recursive estimator `radiance(scene, ray, depth, settings, rng,
// count)` (incident_radiance), produced in bulk by A3Producer: the student's estimator
// (LocalSubject) or a known-wrong one (diagnosis_test.cpp). No test and no verdict here: the
// subject program includes it.

#include <cstdint>
#include <vector>

#include "assignments/subject/requests.hpp"
#include "core/rng.hpp"
#include "render/recursive_estimator.hpp"
#include "render/scene.hpp"
#include "sampling/sphere.hpp"

namespace mcrt::testing::assignment {

template <class Radiance>
struct A3Producer {
  Radiance radiance;

  /// One call from `origin` along `direction` in the furnace (albedo, emission), N branches,
  /// depth k, from Rng(seed, stream): its channel-mean radiance and its rays.
  PathSample recursive_single(double albedo, double emission, Vec3 origin, Vec3 direction, int n,
                              int k, std::uint64_t seed, std::uint64_t stream) const {
    const Scene furnace = make_furnace(albedo, emission);
    Rng rng(seed, stream);
    RayCount count;
    const double L =
        average(radiance(furnace, Ray{origin, direction}, 0, RecursiveSettings{n, k}, rng, count));
    return {L, count.rays};
  }

  /// `samples` calls from the furnace's centre (albedo, Le = 1) in uniformly random directions,
  /// call i from the stream (block, i) of seed: their channel-mean radiance.
  std::vector<double> recursive_furnace(double albedo, int n, int k, int samples,
                                        std::uint64_t seed, std::uint64_t block) const {
    const Scene furnace = make_furnace(albedo, 1.0);
    std::vector<double> values;
    values.reserve(static_cast<std::size_t>(samples));
    RayCount count;
    for (int i = 0; i < samples; ++i) {
      Rng rng(seed, stream_index(block, static_cast<std::uint64_t>(i)));
      const Ray ray{Vec3(0.0), sample_uniform_sphere(rng.uniform2())};
      values.push_back(average(radiance(furnace, ray, 0, RecursiveSettings{n, k}, rng, count)));
    }
    return values;
  }
};

template <class Radiance>
A3Producer<Radiance> a3_producer(Radiance radiance) {
  return {radiance};
}

}  // namespace mcrt::testing::assignment
