#pragma once
// The closest hit on the plain layers: intersect_distance looped over every primitive. The
// reference of tests/render/scene_closest_hit_test.cpp and the loop of render/path_tracer_plain_layers.hpp.

#include <cstddef>
#include <optional>

#include "geometry/hit.hpp"
#include "render/scene.hpp"

namespace mcrt::testing {

/// The nearest hit in `range` by one intersect_distance per primitive, spheres first; the
/// first strictly nearer hit wins, as in Scene::closest_hit.
inline std::optional<Hit> plain_closest_hit(const Scene& scene, const Ray& ray,
                                            Interval range = {}) {
  std::optional<Hit> hit;
  for (const Sphere& s : scene.spheres())
    if (const auto t = intersect_distance(s, ray, range)) {
      range.max = *t;
      hit = hit_at(s, ray, *t);
    }
  for (std::size_t i = 0; i < scene.quads().size(); ++i)
    if (const auto t = intersect_distance(scene.quads()[i], ray, range)) {
      range.max = *t;
      hit = hit_at(scene.quads()[i], ray, *t);
      hit->material = scene.quad_face_material(i, ray.direction);  // a one-sided lamp's back
    }
  return hit;
}

}  // namespace mcrt::testing
