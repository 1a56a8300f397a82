#pragma once
/// Text on images: a built-in 5x7 bitmap font (with one descender row) for labels on contact
/// sheets and figures. Printable ASCII only; any other character draws as '?'.

#include <string_view>

#include "core/math.hpp"
#include "render/image.hpp"

namespace mcrt {

/// Font geometry in font pixels: a glyph is 5 wide and 8 tall (7 rows above the baseline plus
/// one descender row); glyphs advance by 6, leaving one blank column between characters.
inline constexpr int k_glyph_width = 5;
inline constexpr int k_glyph_height = 8;
inline constexpr int k_glyph_advance = k_glyph_width + 1;

/// Number of glyphs `text` draws as: one per byte, except that a multi-byte UTF-8 character
/// counts once (it draws as a single '?').
int glyph_count(std::string_view text);

/// Width and height in image pixels of `text` drawn with the built-in font at `scale`.
/// Width = (6 n - 1) scale for n glyphs (no blank column after the last), 0 for empty text;
/// height = 8 scale. Throws std::invalid_argument if scale < 1 or the size overflows int.
int text_width(std::string_view text, int scale = 2);
int text_height(int scale = 2);

/// Draws `text` with its top-left corner at (x, y); each font pixel is a scale x scale block
/// of `color`; pixels outside the image are skipped. Characters the font lacks draw as '?'.
/// Only the glyphs' set pixels are written: the background shows through.
/// Throws std::invalid_argument if scale < 1.
void draw_text(Image& image, int x, int y, std::string_view text, Color color, int scale = 2);

}  // namespace mcrt
