// sRGB transfer curve, PNG and PFM output, and atomic writes.

#include <cstring>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "io/image_file.hpp"
#include "io/output.hpp"
#include "support/temp_files.hpp"

using namespace mcrt;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  return mcrt::testing::temp_suite_dir("image_test") / name;
}

// Every channel counts once: (r + g + b) / 3 per pixel, then the mean over pixels. Distinct
// channels, so a channel counted twice or left out changes the value (grey images cannot).
TEST(MeanRadianceTest, AveragesTheThreeChannelsOfEveryPixel) {
  EXPECT_EQ(mcrt::average(mcrt::Color(1.0, 2.0, 6.0)), 3.0);
  mcrt::Image image(2, 1);
  image.at(0, 0) = mcrt::Color(1.0, 2.0, 6.0);   // average 3
  image.at(1, 0) = mcrt::Color(0.0, 0.0, 12.0);  // average 4
  EXPECT_EQ(mcrt::mean_radiance(image), 3.5);
}

TEST(SrgbTest, RoundTripAndKnownValues) {
  for (double v = 0.0; v <= 1.0; v += 1.0 / 64)
    EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 1e-12);  // exact inverse up to round-off
  EXPECT_EQ(srgb_encode(0.0), 0.0);
  EXPECT_NEAR(srgb_encode(1.0), 1.0, 1e-12);
  EXPECT_NEAR(srgb_encode(0.18), 0.4613, 1e-4);  // middle grey: ~46% code value (table value)
  EXPECT_EQ(srgb_encode(-1.0), 0.0);             // clamped
  EXPECT_NEAR(srgb_encode(7.0), 1.0, 1e-12);
}

TEST(PfmTest, WriteThenReadBackIsExactInFloat) {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = Color(x, y, 0.125 * (x + 10 * y) + 1e-3);
  const fs::path path = scratch("round_trip.pfm");
  write_pfm(path, image);
  const Image back = read_pfm(path);
  ASSERT_EQ(back.width, 5);
  ASSERT_EQ(back.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(back.at(x, y)[c], static_cast<double>(static_cast<float>(image.at(x, y)[c])));
}

TEST(PfmTest, BottomRowIsStoredFirst) {
  Image image(1, 2);
  image.at(0, 0) = Color(1.0);  // top
  const std::string bytes = encode_pfm(image);
  const std::string header = "PF\n1 2\n-1.0\n";
  ASSERT_EQ(bytes.substr(0, header.size()), header);
  float first;
  std::memcpy(&first, bytes.data() + header.size(), sizeof first);
  EXPECT_EQ(first, 0.0f);  // the bottom row, black, comes first
}

TEST(PngTest, EncodesAValidPng) {
  const std::string png = encode_png(Image(4, 4, Color(0.5)));
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(OutputTest, AtomicWriteLeavesOnlyTheFinalFile) {
  const fs::path path = scratch("atomic.txt");
  write_file_atomic(path, "first");
  write_file_atomic(path, "second");
  std::ifstream file(path);
  std::string text;
  file >> text;
  EXPECT_EQ(text, "second");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(path.parent_path()))
    files += entry.path().filename().string().find("atomic.txt") != std::string::npos;
  EXPECT_EQ(files, 1);  // no temporary left beside it
}

TEST(OutputTest, UnwritableFolderThrowsIoErrorAndLeavesNothing) {
  EXPECT_THROW(write_file_atomic("/proc/mcrt/nope.txt", "x"), IoError);
  EXPECT_THROW(prepare_output_dir("/proc/mcrt"), IoError);
  const fs::path blocker = scratch("a_file");
  write_file_atomic(blocker, "x");
  EXPECT_THROW(prepare_output_dir(blocker / "sub"), IoError);
}

}  // namespace
