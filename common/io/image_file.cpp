#include "io/image_file.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <charconv>
#include <cctype>
#include <cerrno>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <stb_image_write.h>

#include "io/exclusive_file.hpp"
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
      rgb[3 * i + c] =
          static_cast<unsigned char>(std::lround(255.0 * srgb_encode(image.pixels[i][c])));
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
  std::string bytes =
      "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
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

Image decode_pfm(std::string_view bytes, const std::string& name) {
  // The header: "PF", width, height, scale, each ended by one whitespace character.
  std::size_t pos = 0;
  const auto token = [&]() -> std::string_view {
    while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    const std::size_t begin = pos;
    while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
    return bytes.substr(begin, pos - begin);
  };
  const std::string_view magic = token(), width_text = token(), height_text = token(),
                         scale_text = token();
  ++pos;  // the single whitespace character after the scale
  long long width = 0, height = 0;
  double scale = 0.0;
  const auto number = [](std::string_view text, auto& value) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
  };
  if (magic != "PF" || !number(width_text, width) || !number(height_text, height) ||
      !number(scale_text, scale) || width <= 0 || height <= 0 || scale == 0.0 ||
      !std::isfinite(scale) || width > (1 << 20) || height > (1 << 20) || pos > bytes.size())
    throw IoError("'" + name + "' is not a colour PFM file");
  // The size the header promises, checked before a pixel is allocated.
  const auto floats = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3;
  const std::size_t expected = pos + floats * sizeof(float);
  if (bytes.size() != expected)
    throw IoError(fmt::format("'{}' holds {} bytes, but its header ({}x{}) needs {}", name,
                              bytes.size(), width, height, expected));
  Image image(static_cast<int>(width), static_cast<int>(height));
  const bool swap = (scale > 0.0) != (std::endian::native == std::endian::big);
  const char* in = bytes.data() + pos;
  for (int y = image.height - 1; y >= 0; --y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) {
        std::uint32_t bits = 0;
        std::memcpy(&bits, in, sizeof bits);
        in += sizeof bits;
        if (swap) bits = __builtin_bswap32(bits);
        float v;
        std::memcpy(&v, &bits, sizeof v);
        image.at(x, y)[c] = v;
      }
  return image;
}

Image read_pfm(const std::filesystem::path& path) {
  const std::string name = path.string();
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0)
    throw IoError("cannot open '" + name + "': " + std::strerror(errno));
  if (!S_ISREG(status.st_mode))  // a FIFO would block the open, a device read forever
    throw IoError("'" + name + "' is not a regular file");
  // O_NONBLOCK: a file swapped for a FIFO after the stat is not waited on.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw IoError("cannot open '" + name + "': " + std::strerror(errno));
  std::string bytes;
  const bool regular = ::fstat(fd, &status) == 0 && S_ISREG(status.st_mode);
  // A PFM of the largest image (16384 x 16384 floats x 3) and its header, no more.
  constexpr off_t k_largest_pfm = off_t{16384} * 16384 * 12 + 64;
  if (regular && status.st_size <= k_largest_pfm) {
    bytes.resize(static_cast<std::size_t>(status.st_size));
    bytes.resize(read_all(fd, bytes));
  }
  ::close(fd);
  if (!regular) throw IoError("'" + name + "' is not a regular file");
  if (status.st_size > k_largest_pfm) throw IoError("'" + name + "' is too large for a PFM file");
  return decode_pfm(bytes, name);
}

void write_png(const std::filesystem::path& path, const Image& image) {
  write_file_atomic(path, encode_png(image));
}

void write_pfm(const std::filesystem::path& path, const Image& image) {
  write_file_atomic(path, encode_pfm(image));
}

}  // namespace mcrt
