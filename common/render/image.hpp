#pragma once
/// A linear RGB image (row 0 at the top): what the pixel loop fills. io/image_file.hpp writes
/// it as PNG or PFM.

#include <cstddef>
#include <vector>

#include "core/math.hpp"

namespace mcrt {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;  ///< row-major, row 0 at the top

  Image() = default;
  Image(int w, int h, Color fill = Color(0.0))
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}

  Color& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Color& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

/// Mean of average(pixel) over the image.
inline double mean_radiance(const Image& image) {
  double sum = 0.0;
  for (const Color& c : image.pixels) sum += average(c);
  return image.pixels.empty() ? 0.0 : sum / static_cast<double>(image.pixels.size());
}

}  // namespace mcrt
