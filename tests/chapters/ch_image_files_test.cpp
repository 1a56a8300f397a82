// Every image a chapter writes twice, as a PNG for people and a PFM for analysis, says the same
// thing in both: each PNG code value (decoded by stb_image) is the sRGB encoding of the PFM's
// linear value beside it (read by the independent reader of tests/io/image_file_decoding.hpp),
// within one code value (the PFM holds floats, the PNG was encoded from doubles: rounding the
// float can move a value across a code boundary, never further).
//
// The file's name matches the chapter tests' glob but no chapter: it runs chapters 01 and 05.

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "chapters/run_program.hpp"
#include "io/image_file_decoding.hpp"

using namespace mcrt::testing;
namespace fs = std::filesystem;

namespace {

struct Counts {
  int pairs = 0;      // PNG + PFM pairs compared
  int values = 0;     // channel values compared
  int mid_range = 0;  // of them, with a code value strictly between 0 and 255
};

// Compares every PNG in `dir` that has a PFM of the same stem beside it.
Counts expect_png_encodes_pfm(const fs::path& dir) {
  Counts counts;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".png") continue;
    fs::path pfm_path = entry.path();
    pfm_path.replace_extension(".pfm");
    if (!fs::exists(pfm_path)) continue;
    ++counts.pairs;
    const DecodedPng png = decode_png(read_text(entry.path()));
    const PfmPixels pfm = read_pfm_bytes(read_text(pfm_path));
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(png.width, pfm.width) << name;
    EXPECT_EQ(png.height, pfm.height) << name;
    EXPECT_EQ(png.channels, 3) << name;
    if (png.width != pfm.width || png.height != pfm.height || png.channels != 3) continue;
    int off = 0;
    for (int y = 0; y < png.height; ++y)
      for (int x = 0; x < png.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const int code = png.at(x, y, c);
          const int expected = srgb_code(pfm.at(x, y, c));
          ++counts.values;
          counts.mid_range += code > 0 && code < 255;
          if (std::abs(code - expected) > 1 && off++ < 5)
            ADD_FAILURE() << name << " pixel (" << x << ", " << y << ") channel " << c
                          << ": PNG code " << code << ", sRGB of the PFM's " << pfm.at(x, y, c)
                          << " is " << expected;
        }
    EXPECT_EQ(off, 0) << name << ": values more than one code away";
  }
  return counts;
}

TEST(ImageFilesTest, Ch05PngsAreTheSrgbEncodingOfThePfmsBesideThem) {
  const auto dir = fresh_dir("image_files_ch05");
  const ProgramRun run =
      run_program("ch05_path_tracer",
                  "--width 24 --height 18 --spp 4,32 --depth 4 --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Counts counts = expect_png_encodes_pfm(dir);
  EXPECT_EQ(counts.pairs, 2);
  // The comparison saw real grey levels, not only black: 292 of the 2592 values at these flags
  // (most of a 4-spp cornell box is still black).
  EXPECT_GT(counts.mid_range, 100);
}

TEST(ImageFilesTest, Ch01PngIsTheSrgbEncodingOfThePfmBesideIt) {
  const auto dir = fresh_dir("image_files_ch01");
  const ProgramRun run =
      run_program("ch01_ray_tracing",
                  "--width 32 --height 24 --spp 2 --quiet --out " + dir.string());
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Counts counts = expect_png_encodes_pfm(dir);
  EXPECT_EQ(counts.pairs, 1);
  EXPECT_GT(counts.mid_range, counts.values / 4);
}

}  // namespace
