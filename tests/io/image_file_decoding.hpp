#pragma once
// Image files read back by code that shares nothing with common/io/image_file.cpp, for the
// tests that check what people see:
//  - decode_png: stb_image's decoder (libstb-dev), a different library from the writer's;
//  - read_pfm_bytes: a PFM reader written from the format's specification (header "PF",
//    width, height, scale; rows bottom to top; the sign of the scale gives the byte order:
//    negative little-endian, positive big-endian), assembling floats byte by byte so it does
//    not depend on the machine's byte order;
//  - srgb_code: the sRGB curve of IEC 61966-2-1 written out again, as an 8-bit code value.
// Each executable that includes this header compiles stb_image once, with static linkage.

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace mcrt::testing {

/// 8-bit pixels as a decoder returns them: row 0 at the top, `channels` bytes per pixel.
struct DecodedPng {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> bytes;
  std::uint8_t at(int x, int y, int c) const {
    return bytes[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)) *
                     static_cast<std::size_t>(channels) +
                 static_cast<std::size_t>(c)];
  }
};

inline DecodedPng decode_png(const std::string& file_bytes) {
  DecodedPng png;
  unsigned char* data =
      stbi_load_from_memory(reinterpret_cast<const unsigned char*>(file_bytes.data()),
                            static_cast<int>(file_bytes.size()), &png.width, &png.height,
                            &png.channels, 0);
  if (!data)
    throw std::runtime_error(std::string("stb_image cannot decode: ") + stbi_failure_reason());
  png.bytes.assign(data, data + static_cast<std::size_t>(png.width) *
                                    static_cast<std::size_t>(png.height) *
                                    static_cast<std::size_t>(png.channels));
  stbi_image_free(data);
  return png;
}

/// A colour PFM's floats, row 0 at the top (already turned round from the file's order).
struct PfmPixels {
  int width = 0, height = 0;
  double scale = 0.0;      ///< as written in the header (its sign is the byte order)
  std::vector<float> rgb;  ///< 3 floats per pixel, row-major, row 0 at the top
  float at(int x, int y, int c) const {
    return rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x)) *
                   3 +
               static_cast<std::size_t>(c)];
  }
};

inline PfmPixels read_pfm_bytes(const std::string& file) {
  std::size_t pos = 0;
  auto skip_space = [&] {
    while (pos < file.size() && std::isspace(static_cast<unsigned char>(file[pos]))) ++pos;
  };
  auto token = [&] {
    skip_space();
    const std::size_t start = pos;
    while (pos < file.size() && !std::isspace(static_cast<unsigned char>(file[pos]))) ++pos;
    if (start == pos) throw std::runtime_error("PFM header ends early");
    return file.substr(start, pos - start);
  };
  if (token() != "PF") throw std::runtime_error("not a colour PFM (magic is not PF)");
  PfmPixels pfm;
  pfm.width = std::stoi(token());
  pfm.height = std::stoi(token());
  pfm.scale = std::stod(token());
  ++pos;  // exactly one whitespace character ends the header
  if (pfm.width <= 0 || pfm.height <= 0 || pfm.scale == 0.0)
    throw std::runtime_error("bad PFM header");
  const bool little_endian = pfm.scale < 0.0;
  const std::size_t count =
      static_cast<std::size_t>(pfm.width) * static_cast<std::size_t>(pfm.height) * 3;
  if (file.size() - pos != count * 4) throw std::runtime_error("PFM raster has the wrong size");
  pfm.rgb.resize(count);
  for (int row = 0; row < pfm.height; ++row) {  // row 0 of the file is the image's bottom row
    const int y = pfm.height - 1 - row;
    for (int x = 0; x < pfm.width; ++x)
      for (int c = 0; c < 3; ++c) {
        std::uint32_t bits = 0;
        for (int k = 0; k < 4; ++k) {
          const auto byte = static_cast<std::uint32_t>(static_cast<unsigned char>(file[pos++]));
          bits |= byte << (little_endian ? 8 * k : 8 * (3 - k));
        }
        float v;
        std::memcpy(&v, &bits, sizeof v);
        pfm.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(pfm.width) +
                 static_cast<std::size_t>(x)) *
                    3 +
                static_cast<std::size_t>(c)] = v;
      }
  }
  return pfm;
}

/// The 8-bit sRGB code value of a linear value: clamp to [0, 1], then 12.92 v below the knee
/// v = 0.0031308, 1.055 v^(1/2.4) - 0.055 above it; times 255, rounded to nearest.
inline int srgb_code(double linear) {
  const double v = linear < 0.0 ? 0.0 : (linear > 1.0 ? 1.0 : linear);
  const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::floor(255.0 * encoded + 0.5));
}

}  // namespace mcrt::testing
