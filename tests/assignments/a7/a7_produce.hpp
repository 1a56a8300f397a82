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

}  // namespace mcrt::testing::assignment
