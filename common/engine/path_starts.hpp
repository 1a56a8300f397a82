#pragma once
/// The starts of a row's paths, made a block at a time for the four-lane engine
/// (engine/path_tracer_lanes.cpp). For sample s of pixel x in row y, render() does
///
///   Rng rng(seed, stream_index(y width + x, first_sample + s));
///   Ray ray = camera.generate_ray(x, y, rng.uniform2());
///
/// and a start is what that leaves: the generator after its two draws, and the ray.
/// make_path_starts_avx2 makes four starts at once, one instruction per operation in the
/// one-path code's order (the 64-bit products from 32-bit ones, exactly), so every start keeps
/// the one-path code's bits; make_path_starts_portable makes them one at a time
/// (tests/engine/path_starts_test.cpp holds the two to Rng and Camera bit for bit).

#include <cstdint>

#include "geometry/camera.hpp"
#include "geometry/ray.hpp"
#include "render/render.hpp"

namespace mcrt {

/// A sample of a row: pixel x and its sample number. A row's samples are taken in the order
/// x spp + sample.
struct RowSample {
  int x = 0;
  int sample = 0;
  void advance(int spp) {
    if (++sample == spp) {
      sample = 0;
      ++x;
    }
  }
};

/// Up to k_capacity starts, entry i in array position i.
struct PathStarts {
  static constexpr int k_capacity = 64;         // 4 KiB: the block stays in the first-level cache
  alignas(32) std::uint64_t state[k_capacity];  ///< PCG32's state after the two draws
  alignas(32) std::uint64_t increment[k_capacity];  ///< PCG32's increment: 2 stream + 1
  alignas(32) double origin[3][k_capacity];
  alignas(32) double direction[3][k_capacity];

  Ray ray(int i) const {
    return {{origin[0][i], origin[1][i], origin[2][i]},
            {direction[0][i], direction[1][i], direction[2][i]}};
  }
};

/// The starts of the `count` samples of row y from `next` on, in order (count <=
/// k_capacity); `next` is moved past them. AVX2 where the processor has it.
void make_path_starts(const Camera& camera, const RenderSettings& settings, int y, RowSample& next,
                      int count, PathStarts& starts);
void make_path_starts_portable(const Camera& camera, const RenderSettings& settings, int y,
                               RowSample& next, int count, PathStarts& starts);
void make_path_starts_avx2(const Camera& camera, const RenderSettings& settings, int y,
                           RowSample& next, int count, PathStarts& starts);

}  // namespace mcrt
