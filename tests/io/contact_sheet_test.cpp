// The label font (text_width, text_height, draw_text) and contact sheets (make_contact_sheet,
// crop, upscale_nearest). Everything here is exact integer geometry and copied values: the
// tests compare with ==, have no tolerance and cannot fail by chance.

#include <algorithm>
#include <climits>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "io/contact_sheet.hpp"
#include "io/labelled_grid.hpp"
#include "io/text.hpp"

using namespace mcrt;

namespace {

// Sentinel colours no glyph or test image uses, so every written pixel can be told apart.
const Color k_background(-1.0, -2.0, -3.0);
const Color k_ink(0.25, 0.5, 0.75);

std::string printable_ascii() {
  std::string text;
  for (char c = ' '; c <= '~'; ++c) text += c;
  return text;
}

// The text drawn at (0, 0) on a canvas exactly its size, as a string of '#' and '.'.
std::string rendering(std::string_view text, int scale = 1) {
  Image canvas(text_width(text, scale), text_height(scale), k_background);
  draw_text(canvas, 0, 0, text, k_ink, scale);
  std::string bits;
  for (const Color& c : canvas.pixels) bits += c == k_ink ? '#' : '.';
  return bits;
}

// Number of pixels the text inks.
int ink_count(std::string_view text, int scale) {
  const std::string bits = rendering(text, scale);
  return static_cast<int>(std::count(bits.begin(), bits.end(), '#'));
}

int count_pixels(const Image& image, const Color& color) {
  int n = 0;
  for (const Color& c : image.pixels) n += c == color;
  return n;
}

// A w x h image whose every pixel is different from every other test image's: (id, x, y).
Image numbered_image(int id, int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = Color(id, x, y);
  return image;
}

TEST(TextTest, WidthAndHeightArithmetic) {
  EXPECT_EQ(text_width("", 2), 0);
  EXPECT_GT(text_width("a", 1), 0);
  // Widths add up glyph by glyph and grow linearly with the scale.
  EXPECT_EQ(text_width("N=4 k=3", 1),
            text_width("N=4", 1) + text_width(" ", 1) + text_width("k=3", 1));
  EXPECT_EQ(text_width("1 spp"), 2 * text_width("1 spp", 1));  // default scale 2
  EXPECT_EQ(text_width("\xC3\xA9", 3), text_width("?", 3));    // UTF-8 'e acute' is one glyph
  EXPECT_GE(text_height(1), 7);  // capitals are 7 units tall, descenders reach below
  EXPECT_EQ(text_height(), 2 * text_height(1));
  EXPECT_EQ(text_height(3), 3 * text_height(1));
  EXPECT_THROW(text_width("a", 0), std::invalid_argument);
  EXPECT_THROW(text_height(-1), std::invalid_argument);
  EXPECT_THROW(text_height(INT_MAX), std::invalid_argument);  // height x scale overflows int
  EXPECT_THROW(text_width("ab", INT_MAX / 6), std::invalid_argument);
}

TEST(TextTest, DrawsOnlyInsideItsBoxAndOnlyInTheTextColour) {
  const std::string text = printable_ascii();
  const int scale = 2, x0 = 7, y0 = 5;
  Image image(text_width(text, scale) + 20, text_height(scale) + 12, k_background);
  draw_text(image, x0, y0, text, k_ink, scale);
  int inked = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Color& c = image.at(x, y);
      if (c == k_background) continue;
      EXPECT_EQ(c, k_ink) << "at " << x << "," << y;
      const bool inside =
          x >= x0 && x < x0 + text_width(text, scale) && y >= y0 && y < y0 + text_height(scale);
      EXPECT_TRUE(inside) << "pixel outside the text box at " << x << "," << y;
      ++inked;
    }
  EXPECT_GT(inked, 0);
}

TEST(TextTest, EveryGlyphFitsItsCellIsVisibleAndIsDistinct) {
  std::set<std::string> seen;
  for (char c = '!'; c <= '~'; ++c) {
    // A glyph drawn on a canvas one larger than its box: nothing may land outside the box.
    const int w = text_width(std::string(1, c), 1), h = text_height(1);
    Image canvas(w + 1, h + 1, k_background);
    draw_text(canvas, 0, 0, std::string(1, c), k_ink, 1);
    for (int y = 0; y < canvas.height; ++y)
      for (int x = 0; x < canvas.width; ++x)
        if (x >= w || y >= h) {
          EXPECT_EQ(canvas.at(x, y), k_background) << "glyph '" << c << "' spills";
        }
    EXPECT_GT(count_pixels(canvas, k_ink), 0) << "glyph '" << c << "' is blank";
    // stb_easy_font draws '|' as it draws 'l'; no label of the project uses '|'.
    if (c == '|') continue;
    EXPECT_TRUE(seen.insert(rendering(std::string(1, c))).second)
        << "glyph '" << c << "' looks like an earlier one";
  }
  const std::string space = rendering(" ");
  EXPECT_EQ(space, std::string(space.size(), '.'));  // space draws nothing
}

TEST(TextTest, OneAndSevenDiffer) {
  EXPECT_NE(rendering("1"), rendering("7"));
  EXPECT_NE(rendering("0"), rendering("O"));
  EXPECT_NE(rendering("l"), rendering("1"));
}

TEST(TextTest, EachFontPixelIsAScaleByScaleBlock) {
  const std::string text = printable_ascii();
  const int scale = 3;
  Image small(text_width(text, 1), text_height(1), k_background);
  Image large(text_width(text, scale), text_height(scale), k_background);
  draw_text(small, 0, 0, text, k_ink, 1);
  draw_text(large, 0, 0, text, k_ink, scale);
  for (int y = 0; y < large.height; ++y)
    for (int x = 0; x < large.width; ++x)
      ASSERT_EQ(large.at(x, y), small.at(x / scale, y / scale)) << "at " << x << "," << y;
}

TEST(TextTest, UnknownCharactersDrawAsQuestionMark) {
  const std::string question = rendering("?", 2);
  for (const std::string unknown : {"\x01", "\n", "\t", "\x7f", "\xff", "\xC3\xA9", "\xE2\x88\x9A"})
    EXPECT_EQ(rendering(unknown, 2), question)
        << "for byte 0x" << std::hex << (static_cast<unsigned char>(unknown[0]) + 0);
  EXPECT_EQ(rendering("a\xC3\xA9"
                      "b"),
            rendering("a?b"));                // one glyph per UTF-8 character
  EXPECT_NE(rendering("A"), rendering("?"));  // and known ones are not '?'
}

TEST(TextTest, ClippingAtEveryEdgeMatchesACropOfAnUnclippedDrawing) {
  // Drawn on a small image at (x, y), text must look exactly like the same window of a large
  // canvas it fits on; a write outside the small image would be caught by the sanitizers.
  const std::string text = "Ag?_(x)";
  const int scale = 2, w = 11, h = 9, pad = 100;
  for (int y = -text_height(scale) - 1; y <= h + 1; ++y)
    for (int x = -text_width(text, scale) - 1; x <= w + 1; x += 3) {
      Image small(w, h, k_background);
      Image large(w + 2 * pad, h + 2 * pad, k_background);
      draw_text(small, x, y, text, k_ink, scale);
      draw_text(large, x + pad, y + pad, text, k_ink, scale);
      ASSERT_EQ(small.pixels, crop(large, pad, pad, w, h).pixels) << "at " << x << "," << y;
    }
}

TEST(TextTest, ExtremePositionsDrawNothingAndDoNotOverflow) {
  const std::string text(200, 'W');
  Image image(8, 8, k_background);
  const std::pair<int, int> far_away[] = {
      {INT_MAX, 0},      {INT_MIN, 0}, {0, INT_MAX}, {0, INT_MIN}, {INT_MAX - 3, INT_MAX - 3},
      {INT_MIN, INT_MIN}};
  for (const auto& [x, y] : far_away) draw_text(image, x, y, text, k_ink, 1000);
  EXPECT_EQ(count_pixels(image, k_background), 64);
  // The fourth 'T' starts at x = 0, and its top bar's first font unit covers the whole image.
  const std::string bars(200, 'T');
  ASSERT_EQ(rendering("T").front(), '#');
  draw_text(image, -3 * text_width("T", 1) * 1000, 0, bars, k_ink, 1000);
  EXPECT_EQ(count_pixels(image, k_ink), 64);
}

TEST(ContactSheetTest, SizeFollowsCellsColumnsGapAndLabels) {
  const Image wide = numbered_image(1, 10, 6), small = numbered_image(2, 7, 4);
  const std::vector<LabelledImage> cells = {
      {&wide, "ab"}, {&wide, ""}, {&small, "c"}, {&wide, "d"}, {&wide, "e"}};
  SheetLayout layout;
  layout.columns = 2;
  layout.gap = 3;
  layout.label_scale = 1;
  // A cell is as wide as its widest image or label, as tall as the label band (text height
  // + 2) over the tallest image; 2 columns, 3 rows, gaps of 3 around and between.
  const int cell_width = std::max(10, text_width("ab", 1));
  const int cell_height = text_height(1) + 2 + 6;
  Image sheet = make_contact_sheet(cells, layout);
  EXPECT_EQ(sheet.width, 3 + 2 * (cell_width + 3));
  EXPECT_EQ(sheet.height, 3 + 3 * (cell_height + 3));

  // A title wider than the grid sets the width (2 gaps + its width); its band adds its height
  // + gap.
  layout.title = "Title + more words";
  sheet = make_contact_sheet(cells, layout);
  ASSERT_GT(text_width(layout.title, 1), 2 * (cell_width + 3));
  EXPECT_EQ(sheet.width, 2 * 3 + text_width(layout.title, 1));
  EXPECT_EQ(sheet.height, 3 + text_height(1) + 3 + 3 * (cell_height + 3));

  // More columns than cells: only as many as there are cells; no labels: no band.
  layout.title.clear();
  layout.columns = 9;
  const std::vector<LabelledImage> unlabelled = {{&wide, ""}, {&small, ""}};
  sheet = make_contact_sheet(unlabelled, layout);
  EXPECT_EQ(sheet.width, 3 + 2 * (10 + 3));
  EXPECT_EQ(sheet.height, 3 + 6 + 3);

  // No cells: just the gaps.
  sheet = make_contact_sheet({}, layout);
  EXPECT_EQ(sheet.width, 3);
  EXPECT_EQ(sheet.height, 3);
}

TEST(ContactSheetTest, EachImageIsCopiedToItsCellAndNothingElseIsOverwritten) {
  std::vector<Image> images;
  for (int i = 0; i < 7; ++i)  // two smaller ones: cell 3 narrower, cell 5 shorter
    images.push_back(numbered_image(i + 1, i == 3 ? 9 : 12, i == 5 ? 5 : 8));
  std::vector<LabelledImage> cells;
  for (int i = 0; i < 7; ++i) cells.push_back({&images[i], "k=" + std::to_string(i)});
  SheetLayout layout;
  layout.columns = 3;
  layout.gap = 5;
  layout.label_scale = 2;
  layout.background = k_background;
  layout.label_color = k_ink;
  layout.title = "T";
  const Image sheet = make_contact_sheet(cells, layout);

  // Labels "k=i" at scale 2 over images up to 12 x 8: band = text height + 2 scale; the title
  // band is its text height + gap.
  int widest_label = 0;
  for (const LabelledImage& cell : cells)
    widest_label = std::max(widest_label, text_width(cell.label, 2));
  const int cell_width = std::max(12, widest_label), band = text_height(2) + 4;
  const int cell_height = band + 8, title_band = text_height(2) + 5;
  ASSERT_EQ(sheet.width, 5 + 3 * (cell_width + 5));
  ASSERT_EQ(sheet.height, 5 + title_band + 3 * (cell_height + 5));
  int image_pixels = 0;
  for (int i = 0; i < 7; ++i) {
    const int x0 = 5 + (i % 3) * (cell_width + 5);
    const int y0 = 5 + title_band + (i / 3) * (cell_height + 5);
    const Image& image = images[i];
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x)
        ASSERT_EQ(sheet.at(x0 + x, y0 + band + y), image.at(x, y)) << "cell " << i;
    // The band holds this cell's label and background only.
    const Image label_band = crop(sheet, x0, y0, cell_width, band);
    EXPECT_EQ(count_pixels(label_band, k_ink), ink_count(cells[i].label, 2)) << "cell " << i;
    EXPECT_EQ(count_pixels(label_band, k_background) + count_pixels(label_band, k_ink),
              cell_width * band);
    // Below the band, what the image does not cover is background.
    for (int y = 0; y < cell_height - band; ++y)
      for (int x = 0; x < cell_width; ++x)
        if (x >= image.width || y >= image.height) {
          EXPECT_EQ(sheet.at(x0 + x, y0 + band + y), k_background) << "cell " << i;
        }
    image_pixels += image.width * image.height;
  }
  // Everything else is background, label ink or the title: the images appear once each.
  const int ink = count_pixels(sheet, k_ink);
  EXPECT_EQ(count_pixels(sheet, k_background) + ink + image_pixels, sheet.width * sheet.height);
  int expected_ink = ink_count("T", 2);
  for (const LabelledImage& cell : cells) expected_ink += ink_count(cell.label, 2);
  EXPECT_EQ(ink, expected_ink);
}

TEST(ContactSheetTest, LabelIsCentredOverItsImageOrLeftAlignedWhenWider) {
  SheetLayout layout;
  layout.gap = 2;
  layout.label_scale = 1;
  layout.background = k_background;
  layout.label_color = k_ink;
  for (const int image_width : {40, 6}) {
    const Image image = numbered_image(1, image_width, 3);
    const LabelledImage cell{&image, "ab"};
    const Image sheet = make_contact_sheet({&cell, 1}, layout);

    // The expected sheet, built pixel by pixel from the documented geometry.
    const int label_width = text_width("ab", 1);
    const int cell_width = std::max(image_width, label_width), band = text_height(1) + 2;
    Image expected(2 + cell_width + 2, 2 + band + 3 + 2, k_background);
    const int label_x = 2 + std::max(0, (image_width - label_width) / 2);
    draw_text(expected, label_x, 2 + 1, "ab", k_ink, 1);
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) expected.at(2 + x, 2 + band + y) = image.at(x, y);
    ASSERT_EQ(sheet.width, expected.width);
    ASSERT_EQ(sheet.height, expected.height);
    EXPECT_EQ(sheet.pixels, expected.pixels) << "image width " << image_width;
  }
}

TEST(ContactSheetTest, RejectsInvalidLayouts) {
  const Image image = numbered_image(1, 4, 4);
  const LabelledImage good{&image, "a"}, missing{nullptr, "b"};
  SheetLayout layout;
  EXPECT_NO_THROW(make_contact_sheet({&good, 1}, layout));
  EXPECT_THROW(make_contact_sheet({&missing, 1}, layout), std::invalid_argument);
  layout.columns = 0;
  EXPECT_THROW(make_contact_sheet({&good, 1}, layout), std::invalid_argument);
  layout = {};
  layout.gap = -1;
  EXPECT_THROW(make_contact_sheet({&good, 1}, layout), std::invalid_argument);
  layout = {};
  layout.label_scale = 0;
  EXPECT_THROW(make_contact_sheet({&good, 1}, layout), std::invalid_argument);
  layout = {};
  layout.gap = INT_MAX / 2;  // 3 gaps around one cell overflow int
  EXPECT_THROW(make_contact_sheet({&good, 1}, layout), std::invalid_argument);
}

TEST(CropTest, CopiesTheRectangleAndClipsItToTheImage) {
  const Image image = numbered_image(7, 6, 5);
  const Image inside = crop(image, 1, 2, 3, 2);
  ASSERT_EQ(inside.width, 3);
  ASSERT_EQ(inside.height, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_EQ(inside.at(x, y), Color(7, x + 1, y + 2));

  const Image top_left = crop(image, -2, -1, 4, 3);  // keeps [0, 2) x [0, 2)
  ASSERT_EQ(top_left.width, 2);
  ASSERT_EQ(top_left.height, 2);
  EXPECT_EQ(top_left.at(1, 1), Color(7, 1, 1));
  const Image bottom_right = crop(image, 4, 3, INT_MAX, INT_MAX);  // x + w must not overflow
  ASSERT_EQ(bottom_right.width, 2);
  ASSERT_EQ(bottom_right.height, 2);
  EXPECT_EQ(bottom_right.at(0, 0), Color(7, 4, 3));
  EXPECT_EQ(crop(image, INT_MIN, INT_MIN, INT_MAX, INT_MAX).pixels.size(), 0u);
  EXPECT_EQ(crop(image, 0, 0, 6, 5).pixels, image.pixels);

  const std::tuple<int, int, int, int> outside[] = {
      {6, 0, 1, 1}, {0, 5, 1, 1}, {-3, 0, 3, 5}, {0, 0, 0, 5}, {0, 0, 5, -1}};
  for (const auto& [x, y, w, h] : outside) {
    const Image empty = crop(image, x, y, w, h);
    EXPECT_EQ(empty.width, 0);
    EXPECT_EQ(empty.height, 0);
    EXPECT_TRUE(empty.pixels.empty());
  }
}

TEST(UpscaleTest, RepeatsEachPixelFactorByFactorTimes) {
  const Image image = numbered_image(3, 3, 2);
  const Image big = upscale_nearest(image, 4);
  ASSERT_EQ(big.width, 12);
  ASSERT_EQ(big.height, 8);
  for (int y = 0; y < big.height; ++y)
    for (int x = 0; x < big.width; ++x) EXPECT_EQ(big.at(x, y), Color(3, x / 4, y / 4));
  EXPECT_EQ(upscale_nearest(image, 1).pixels, image.pixels);
  EXPECT_TRUE(upscale_nearest(Image(), 5).pixels.empty());
  EXPECT_THROW(upscale_nearest(image, 0), std::invalid_argument);
  EXPECT_THROW(upscale_nearest(image, INT_MAX), std::invalid_argument);  // 3 * factor overflows
}

TEST(BlockMeansTest, EachBlockHoldsItsMeanAndTheLastBlocksAreClipped) {
  // 5 x 3 pixels of value (x, y, 1) in blocks of 2: columns {0,1}, {2,3}, {4}; rows {0,1}, {2}.
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = Color(x, y, 1);
  const Image means = block_means(image, 2);
  ASSERT_EQ(means.width, 5);
  ASSERT_EQ(means.height, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) {
      const double mean_x = x < 4 ? (x / 2) * 2 + 0.5 : 4.0, mean_y = y < 2 ? 0.5 : 2.0;
      EXPECT_EQ(means.at(x, y), Color(mean_x, mean_y, 1)) << x << "," << y;
    }
  EXPECT_EQ(block_means(image, 1).pixels, image.pixels);
  EXPECT_THROW(block_means(image, 0), std::invalid_argument);
}

TEST(BlockMeansTest, TheStripGetsASecondRowOfMeansOnlyWhenAsked) {
  const std::vector<Image> images(3, Image(30, 30, Color(0.5)));
  const std::vector<std::string> labels{"a", "b", "c"};
  const Image one_row = centre_detail_strip(images, labels, "x");
  const Image two_rows = centre_detail_strip(images, labels, "x", 8);
  EXPECT_EQ(two_rows.width, one_row.width);
  EXPECT_GT(two_rows.height, one_row.height + 100);  // a second row of 10 x 10 details, x12
  EXPECT_THROW(centre_detail_strip(images, std::vector<std::string>{"a"}, "x"),
               std::invalid_argument);
}

}  // namespace
