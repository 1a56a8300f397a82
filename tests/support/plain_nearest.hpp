#pragma once
// The plain references for the SIMD sphere and quad sets: a loop over intersect_distance in
// which the first strictly nearer hit wins, returned as the set's Nearest.

#include <cstddef>
#include <vector>

#include "geometry/quad.hpp"
#include "geometry/quad_set.hpp"
#include "geometry/ray.hpp"
#include "geometry/sphere.hpp"
#include "geometry/sphere_set.hpp"

namespace mcrt::testing {

template <class Set, class Shape>
typename Set::Nearest plain_nearest_of(const std::vector<Shape>& shapes, const Ray& ray,
                                       Interval range) {
  typename Set::Nearest best{shapes.size(), range.max};
  for (std::size_t i = 0; i < shapes.size(); ++i)
    if (const auto t = intersect_distance(shapes[i], ray, range)) {
      range.max = *t;
      best = {i, *t};
    }
  return best;
}

inline SphereSet::Nearest plain_nearest(const std::vector<Sphere>& spheres, const Ray& ray,
                                        Interval range) {
  return plain_nearest_of<SphereSet>(spheres, ray, range);
}

inline QuadSet::Nearest plain_nearest(const std::vector<Quad>& quads, const Ray& ray,
                                      Interval range) {
  return plain_nearest_of<QuadSet>(quads, ray, range);
}

}  // namespace mcrt::testing
