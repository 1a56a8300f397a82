#pragma once
// What a7's checks ask of a point set, produced in bulk. LocalSubject answers a7's requests with
// this (the student's point sets); the checks run known-wrong sets through it
// (diagnosis_test.cpp). No test and no verdict here: the subject program includes it.
//   a7.1 JitteredPoints{n, d, key}(i, j)
//   a7.2 LatinHypercubePoints{n, key}(i, j)
//   a7.4 HaltonPoints{n, key}(i, j)
// (a7.3, radical_inverse(i, base), is asked one value at a time.)

#include <cstdint>
#include <vector>

#include "assignments/subject/requests.hpp"
#include "sampling/point_sets.hpp"
#include "sampling/radical_inverse.hpp"

namespace mcrt::testing::assignment {

/// Coordinate j < d of point i of make(n, key), for each key key0, key0 + 1, ... (key_count
/// of them), each index of `indices` and each j: key-major, then index, then dimension.
template <class Make>
std::vector<double> a7_point_values(Make&& make, std::uint32_t n, unsigned d, std::uint64_t key0,
                                    std::uint32_t key_count,
                                    const std::vector<std::uint32_t>& indices) {
  std::vector<double> out;
  out.reserve(std::size_t{key_count} * indices.size() * d);
  for (std::uint32_t r = 0; r < key_count; ++r) {
    const auto points = make(n, key0 + r);
    for (std::uint32_t i : indices)
      for (unsigned j = 0; j < d; ++j) out.push_back(points(i, j));
  }
  return out;
}

/// a7's requests answered by the point set types and the radical inverse given: the student's
/// (LocalSubject: a7_with()), or one of them replaced by a known-wrong one (diagnosis_test.cpp).
template <class Jittered, class Latin, class Halton, class Radical>
struct A7Producer {
  Radical radical;
  std::vector<double> a7_points(A7PointSet kind, std::uint32_t n, unsigned d, std::uint64_t key0,
                                std::uint32_t key_count,
                                const std::vector<std::uint32_t>& indices) const {
    if (kind == A7PointSet::jittered)
      return a7_point_values(
          [d](std::uint32_t m, std::uint64_t k) {
            return Jittered{m, d, k};
          },
          n, d, key0, key_count, indices);
    if (kind == A7PointSet::latin_hypercube)
      return a7_point_values(
          [](std::uint32_t m, std::uint64_t k) {
            return Latin{m, k};
          },
          n, d, key0, key_count, indices);
    return a7_point_values(
        [](std::uint32_t m, std::uint64_t k) {
          return Halton{m, k};
        },
        n, d, key0, key_count, indices);
  }
  std::vector<double> a7_radical_inverse(std::uint32_t base,
                                         const std::vector<std::uint32_t>& indices) const {
    std::vector<double> out;
    for (std::uint32_t i : indices) out.push_back(radical(i, base));
    return out;
  }
};
template <class Jittered = JitteredPoints, class Latin = LatinHypercubePoints,
          class Halton = HaltonPoints, class Radical = double (*)(std::uint32_t, std::uint32_t)>
A7Producer<Jittered, Latin, Halton, Radical> a7_with(Radical radical = &radical_inverse) {
  return {radical};
}

}  // namespace mcrt::testing::assignment
