#pragma once
/// Image files: 8-bit sRGB PNG for people, PFM (linear floats) for analysis.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "render/image.hpp"

namespace mcrt {

/// The sRGB transfer curve: linear [0,1] -> encoded [0,1], and its inverse.
double srgb_encode(double linear);
double srgb_decode(double encoded);

/// 8-bit sRGB PNG bytes of the image (values clamped to [0,1] before encoding).
std::string encode_png(const Image& image);
/// Little-endian PFM ("PF", scale -1) bytes: rows stored bottom to top, as the format says.
std::string encode_pfm(const Image& image);
/// Reads a colour PFM written by any tool (either byte order). Throws IoError on failure: a
/// path that is not a regular file (a FIFO, a device) is refused without being opened, and a
/// header whose size disagrees with the file's is refused before any pixel is allocated.
Image read_pfm(const std::filesystem::path& path);
/// The image of PFM `bytes`; `name` (a file's name) for messages. Exactly width x height x 3
/// floats must follow the header: fewer or more throw IoError, before allocating.
Image decode_pfm(std::string_view bytes, const std::string& name);

/// Atomic writes (temporary file, then rename); throw IoError on failure.
void write_png(const std::filesystem::path& path, const Image& image);
void write_pfm(const std::filesystem::path& path, const Image& image);

}  // namespace mcrt
