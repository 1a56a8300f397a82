#pragma once
/// A linear RGB image (row 0 at the top), written as PNG (sRGB) or PFM (linear floats).

#include <filesystem>
#include <string>
#include <vector>

#include "math.hpp"

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

/// The sRGB transfer curve: linear [0,1] -> encoded [0,1], and its inverse.
double srgb_encode(double linear);
double srgb_decode(double encoded);

/// 8-bit sRGB PNG bytes of the image (values clamped to [0,1] before encoding).
std::string encode_png(const Image& image);
/// Little-endian PFM ("PF", scale -1) bytes: rows stored bottom to top, as the format says.
std::string encode_pfm(const Image& image);
/// Reads a colour PFM written by any tool (either byte order). Throws IoError on failure.
Image read_pfm(const std::filesystem::path& path);

/// Atomic writes (temporary file, then rename); throw IoError on failure.
void write_png(const std::filesystem::path& path, const Image& image);
void write_pfm(const std::filesystem::path& path, const Image& image);

/// Mean of average(pixel) over the image.
double mean_radiance(const Image& image);

}  // namespace mcrt
