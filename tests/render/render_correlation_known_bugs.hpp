#pragma once
// Known-wrong pixel loops whose samples are correlated, for the correlation checks
// (tests/render/render_correlation_checks.cpp; rejected in tests/render/render_correlation_test.cpp). Each renders
// one value (the channel mean) per pixel of the furnace at one sample per pixel, as the real
// render loop does, but keys the pixel's stream wrongly.

#include <cstdint>
#include <vector>

#include "core/rng.hpp"
#include "geometry/camera.hpp"
#include "render/path_tracer.hpp"
#include "render/scene.hpp"

namespace mcrt::testing::known_bugs {

/// The furnace pixel loop with the stream of pixel (x, y), sample s given by `key(x, y, s)`.
template <class Key>
std::vector<double> furnace_pixels_keyed(const Scene& furnace, int width, int height, int depth,
                                         std::uint64_t seed, std::uint64_t sample, Key&& key) {
  const Camera camera(furnace.camera, width, height);
  std::vector<double> values;
  RayCount count;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Rng rng(seed, key(static_cast<std::uint64_t>(x), static_cast<std::uint64_t>(y), sample));
      const Ray ray = camera.generate_ray(x, y, rng.uniform2());
      values.push_back(average(estimate_path_radiance(furnace, ray, depth, rng, count)));
    }
  return values;
}

/// Wrong: the pixel's key is x + y, so the pixels of an anti-diagonal share one stream.
inline std::uint64_t key_x_plus_y(std::uint64_t x, std::uint64_t y, std::uint64_t s) {
  return stream_index(x + y, s);
}

/// Wrong: the key ignores the sample index, so every sample of a pixel is the same sample.
inline std::uint64_t key_ignoring_sample(std::uint64_t x, std::uint64_t y, std::uint64_t) {
  return stream_index((y << 16) + x, 0);
}

}  // namespace mcrt::testing::known_bugs
