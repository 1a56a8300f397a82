#pragma once
// The plain reference for the SIMD sphere set: a loop over intersect_distance in which the
// first strictly nearer hit wins, returned as SphereSet::Nearest.

#include <cstddef>
#include <vector>

#include "geometry/ray.hpp"
#include "geometry/sphere.hpp"
#include "geometry/sphere_set.hpp"

namespace mcrt::testing {

inline SphereSet::Nearest plain_nearest(const std::vector<Sphere>& spheres, const Ray& ray,
                                        Interval range) {
  SphereSet::Nearest best{spheres.size(), range.max};
  for (std::size_t i = 0; i < spheres.size(); ++i)
    if (const auto t = intersect_distance(spheres[i], ray, range)) {
      range.max = *t;
      best = {i, *t};
    }
  return best;
}

}  // namespace mcrt::testing
