#include "io/text.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include <stb_easy_font.h>

namespace mcrt {

namespace {

// stb_easy_font writes each stroke as a quad of 4 vertices: x, y, z as floats and 4 colour
// bytes, in font units with y growing downwards.
struct Vertex {
  float x, y, z;
  unsigned char color[4];
};
static_assert(sizeof(Vertex) == 16);

void check_scale(int scale) {
  if (scale < 1)
    throw std::invalid_argument("text scale must be at least 1, got " + std::to_string(scale));
}

// Start of a UTF-8 character: every byte except the continuation bytes 10xxxxxx.
bool starts_character(char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }

// The strokes of `text` (already printable) as quads, in font units.
std::vector<Vertex> strokes(const std::string& text) {
  // Room for 64 strokes per glyph (the font uses far fewer), 4 vertices each.
  std::vector<Vertex> vertices(text.size() * 64 * 4 + 4);
  std::string buffer = text;  // stb_easy_font takes a mutable char*
  const int quads = stb_easy_font_print(0.0f, 0.0f, buffer.data(), nullptr, vertices.data(),
                                        static_cast<int>(vertices.size() * sizeof(Vertex)));
  vertices.resize(static_cast<std::size_t>(quads) * 4);
  return vertices;
}

// The font's height in font units: the lowest stroke bottom over every printable glyph.
int font_height() {
  static const int height = [] {
    std::string all;
    for (char c = ' '; c <= '~'; ++c) all += c;
    float bottom = 0.0f;
    for (const Vertex& v : strokes(all)) bottom = std::max(bottom, v.y);
    return static_cast<int>(bottom + 0.5f);
  }();
  return height;
}

}  // namespace

std::string printable_text(std::string_view text) {
  std::string printable;
  for (char c : text) {
    if (!starts_character(c)) continue;
    printable += (c >= ' ' && c <= '~') ? c : '?';  // also every byte >= 0x80
  }
  return printable;
}

int glyph_count(std::string_view text) {
  return static_cast<int>(std::count_if(text.begin(), text.end(), starts_character));
}

int text_width(std::string_view text, int scale) {
  check_scale(scale);
  std::string printable = printable_text(text);
  const std::int64_t width = std::int64_t{stb_easy_font_width(printable.data())} * scale;
  if (width > std::numeric_limits<int>::max())
    throw std::invalid_argument("text too wide for an image: " + std::to_string(width) + " pixels");
  return static_cast<int>(width);
}

int text_height(int scale) {
  check_scale(scale);
  if (scale > std::numeric_limits<int>::max() / font_height())
    throw std::invalid_argument("text scale too large: " + std::to_string(scale));
  return font_height() * scale;
}

void draw_text(Image& image, int x, int y, std::string_view text, Color color, int scale) {
  check_scale(scale);
  const std::vector<Vertex> vertices = strokes(printable_text(text));
  // 64-bit positions: a long label far off the image must not overflow int while clipping.
  const std::int64_t s = scale;
  for (std::size_t q = 0; q + 3 < vertices.size(); q += 4) {
    // Vertices 0 and 2 are opposite corners of an axis-aligned stroke, in whole font units.
    const auto x0 = static_cast<std::int64_t>(vertices[q].x),
               y0 = static_cast<std::int64_t>(vertices[q].y);
    const auto x1 = static_cast<std::int64_t>(vertices[q + 2].x);
    const auto y1 = static_cast<std::int64_t>(vertices[q + 2].y);
    const std::int64_t x_begin = std::max<std::int64_t>(x + std::min(x0, x1) * s, 0);
    const std::int64_t x_end = std::min<std::int64_t>(x + std::max(x0, x1) * s, image.width);
    const std::int64_t y_begin = std::max<std::int64_t>(y + std::min(y0, y1) * s, 0);
    const std::int64_t y_end = std::min<std::int64_t>(y + std::max(y0, y1) * s, image.height);
    for (std::int64_t py = y_begin; py < y_end; ++py)
      for (std::int64_t px = x_begin; px < x_end; ++px)
        image.at(static_cast<int>(px), static_cast<int>(py)) = color;
  }
}

}  // namespace mcrt
