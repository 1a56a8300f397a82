#include "io/image_file.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include <stb_image_write.h>

#include "io/output.hpp"

namespace mcrt {

double srgb_encode(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double encoded) {
  return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

std::string encode_png(const Image& image) {
  std::vector<unsigned char> rgb(image.pixels.size() * 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      rgb[3 * i + c] = static_cast<unsigned char>(std::lround(255.0 * srgb_encode(image.pixels[i][c])));
  std::string bytes;
  auto append = [](void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), size);
  };
  if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, rgb.data(),
                              image.width * 3))
    throw IoError("PNG encoding failed");
  return bytes;
}

std::string encode_pfm(const Image& image) {
  static_assert(std::endian::native == std::endian::little, "PFM writer assumes little-endian");
  std::string bytes = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) +
                      "\n-1.0\n";
  const std::size_t header = bytes.size();
  bytes.resize(header + image.pixels.size() * 3 * sizeof(float));
  char* out = bytes.data() + header;
  for (int y = image.height - 1; y >= 0; --y)  // PFM stores the bottom row first
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = static_cast<float>(image.at(x, y)[c]);
        std::memcpy(out, &v, sizeof v);
        out += sizeof v;
      }
  return bytes;
}

Image read_pfm(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw IoError("cannot open '" + path.string() + "'");
  std::string magic;
  int width = 0, height = 0;
  double scale = 0.0;
  file >> magic >> width >> height >> scale;
  file.get();  // the single whitespace character after the scale
  if (!file || magic != "PF" || width <= 0 || height <= 0 || scale == 0.0)
    throw IoError("'" + path.string() + "' is not a colour PFM file");
  Image image(width, height);
  const bool swap = (scale > 0.0) != (std::endian::native == std::endian::big);
  for (int y = height - 1; y >= 0; --y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        std::uint32_t bits = 0;
        file.read(reinterpret_cast<char*>(&bits), sizeof bits);
        if (swap) bits = __builtin_bswap32(bits);
        float v;
        std::memcpy(&v, &bits, sizeof v);
        image.at(x, y)[c] = v;
      }
  if (!file) throw IoError("'" + path.string() + "' is truncated");
  return image;
}

void write_png(const std::filesystem::path& path, const Image& image) {
  write_file_atomic(path, encode_png(image));
}

void write_pfm(const std::filesystem::path& path, const Image& image) {
  write_file_atomic(path, encode_pfm(image));
}

}  // namespace mcrt
