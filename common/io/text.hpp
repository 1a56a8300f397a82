#pragma once
/// Text on images: labels on contact sheets and figures, drawn with stb_easy_font (libstb-dev),
/// a small segment font of printable ASCII. Any other character draws as '?', a multi-byte
/// UTF-8 character as one '?'.

#include <string>
#include <string_view>

#include "core/math.hpp"
#include "render/image.hpp"

namespace mcrt {

/// The text as the font draws it: printable ASCII kept, every other character (a multi-byte
/// UTF-8 character counts once) replaced by '?'.
std::string printable_text(std::string_view text);

/// Number of glyphs `text` draws as.
int glyph_count(std::string_view text);

/// Width and height in image pixels of `text` drawn at `scale` (each font unit a scale x scale
/// block). The width is the font's advance summed over the glyphs (0 for empty text); the
/// height covers every glyph from its top to the bottom of its descender. Throws
/// std::invalid_argument if scale < 1 or the size overflows int.
int text_width(std::string_view text, int scale = 2);
int text_height(int scale = 2);

/// Draws `text` with its top-left corner at (x, y) in `color`; pixels outside the image are
/// skipped and only the glyphs' strokes are written: the background shows through. Every
/// written pixel lies inside the text_width x text_height box at (x, y).
/// Throws std::invalid_argument if scale < 1.
void draw_text(Image& image, int x, int y, std::string_view text, Color color, int scale = 2);

}  // namespace mcrt
