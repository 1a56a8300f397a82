// What people see: the PNG's code values, decoded by stb_image (not by the writer's library),
// against the sRGB curve; and the PFM's floats, read by a reader written from the format's
// specification, against the image (tests/io/image_file_decoding.hpp).

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "io/image_file.hpp"
#include "io/image_file_decoding.hpp"

using namespace mcrt;
using mcrt::testing::decode_png;
using mcrt::testing::read_pfm_bytes;
using mcrt::testing::srgb_code;

namespace {

// Known linear values and their 8-bit sRGB code values (IEC 61966-2-1; 255 x encoded,
// rounded; 0.5 gives 187.52, 0.18 gives 117.65): 0.0031308 is the knee where the linear segment 12.92 v meets the power curve.
struct KnownCode {
  double linear;
  int code;
};
constexpr KnownCode k_known_codes[] = {
    {0.0, 0},   {0.001, 3}, {0.0031308, 10}, {0.01, 25}, {0.18, 118},  {0.25, 137},
    {0.5, 188}, {0.9, 243}, {1.0, 255},      {1.5, 255}, {100.0, 255}, {-0.25, 0},
};

TEST(PngEncodingTest, KnownLinearValuesGiveTheirSrgbCodeValues) {
  // One pixel per known value, each channel the same; decoded by stb_image.
  const int n = static_cast<int>(std::size(k_known_codes));
  Image image(n, 1);
  for (int i = 0; i < n; ++i) image.at(i, 0) = Color(k_known_codes[i].linear);
  const auto png = decode_png(encode_png(image));
  ASSERT_EQ(png.width, n);
  ASSERT_EQ(png.height, 1);
  ASSERT_EQ(png.channels, 3);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(png.at(i, 0, c), k_known_codes[i].code) << "linear " << k_known_codes[i].linear;
}

TEST(PngEncodingTest, EveryCodeValueOfARampMatchesTheCurve) {
  // 4096 linear values over [0, 1.25] (the last fifth clamps), in a 64 x 64 image whose
  // channels differ, so a swapped channel, a flipped row or a transposed image shows too.
  const int side = 64;
  Image image(side, side);
  auto linear = [&](int x, int y, int c) {
    const int i = (y * side + x + 1365 * c) % (side * side);
    return 1.25 * i / (side * side - 1);
  };
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      image.at(x, y) = Color(linear(x, y, 0), linear(x, y, 1), linear(x, y, 2));
  const auto png = decode_png(encode_png(image));
  ASSERT_EQ(png.width, side);
  ASSERT_EQ(png.height, side);
  int mismatches = 0;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      for (int c = 0; c < 3; ++c) mismatches += png.at(x, y, c) != srgb_code(linear(x, y, c));
  EXPECT_EQ(mismatches, 0);
}

TEST(PngEncodingTest, NonSquareImageKeepsRowsAndColumns) {
  Image image(5, 3);  // one bright pixel near the top-right corner
  image.at(3, 0) = Color(1.0, 0.0, 0.18);
  const auto png = decode_png(encode_png(image));
  ASSERT_EQ(png.width, 5);
  ASSERT_EQ(png.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      const bool lit = x == 3 && y == 0;
      EXPECT_EQ(png.at(x, y, 0), lit ? 255 : 0) << x << "," << y;
      EXPECT_EQ(png.at(x, y, 1), 0);
      EXPECT_EQ(png.at(x, y, 2), lit ? 118 : 0);
    }
}

TEST(PfmEncodingTest, IndependentReaderSeesTheImageTopRowFirst) {
  Image image(7, 4);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 7; ++x)
      image.at(x, y) = Color(x + 0.5, 10.0 * y + 0.25, -1e-3 * (x + 7 * y));
  const auto pfm = read_pfm_bytes(encode_pfm(image));
  ASSERT_EQ(pfm.width, 7);
  ASSERT_EQ(pfm.height, 4);
  EXPECT_LT(pfm.scale, 0.0);  // the writer promises little-endian
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 7; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(pfm.at(x, y, c), static_cast<float>(image.at(x, y)[c]))
            << x << "," << y << "," << c;
}

// A big-endian PFM (positive scale) written here byte by byte: the project's reader must
// read it as the specification says, and agree with the independent one.
TEST(PfmEncodingTest, ProjectReaderReadsBigEndianFiles) {
  const int width = 3, height = 2;
  std::string file = "PF\n3 2\n1.0\n";
  auto value = [](int x, int y, int c) { return static_cast<float>(100 * y + 10 * x + c) + 0.5f; };
  for (int y = height - 1; y >= 0; --y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = value(x, y, c);
        std::uint32_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        for (int k = 3; k >= 0; --k) file.push_back(static_cast<char>((bits >> (8 * k)) & 0xffu));
      }
  const auto independent = read_pfm_bytes(file);
  const auto path = std::filesystem::temp_directory_path() /
                    ("mcrt_image_encoding_" + std::to_string(::getpid()) + ".pfm");
  { std::ofstream(path, std::ios::binary) << file; }
  const Image project = read_pfm(path);
  std::filesystem::remove(path);
  ASSERT_EQ(project.width, width);
  ASSERT_EQ(project.height, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(independent.at(x, y, c), value(x, y, c));
        EXPECT_EQ(project.at(x, y)[c], static_cast<double>(value(x, y, c)));
      }
}

}  // namespace
