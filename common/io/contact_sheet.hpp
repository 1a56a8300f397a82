#pragma once
/// Contact sheets: several images side by side in a grid, each labelled, for comparing renders
/// (depth against branching factor, noise against samples per pixel). Plus the two helpers
/// such figures need: crop a detail and blow it up without smoothing the noise away.

#include <span>
#include <string>

#include "core/math.hpp"
#include "render/image.hpp"

namespace mcrt {

/// One cell of a contact sheet: an image (not owned; must outlive the call) and its label.
struct LabelledImage {
  const Image* image;
  std::string label;
};

struct SheetLayout {
  int columns = 1;         ///< cells per row; cells fill rows left to right, top to bottom
  int gap = 4;             ///< pixels between cells and around the sheet
  int label_scale = 2;     ///< font scale of the labels
  Color background{0.0};   ///< linear RGB of the gaps and label bands
  Color label_color{1.0};  ///< linear RGB of the label text
  std::string title;       ///< optional line of text across the top of the sheet
};

/// The images in a grid, each under a band holding its label. Cells are sized to the largest
/// image; smaller images sit top-left in their cell. Values stay linear (write_png encodes).
///
/// Geometry, with s = label_scale and c = min(columns, cells.size()) columns:
///   cell width  = the widest image, or the widest label if that is wider
///   band height = text_height(s) + 2 s (0 when every label is empty); the label's top is s
///                 below the band's, centred over its image (left-aligned if wider than it)
///   cell height = band height + the tallest image
///   title band  = text_height(s) + gap at the top (0 without a title), title at (gap, gap)
///   cell (i % c, i / c) has its top-left corner at
///     (gap + col (cell width + gap), gap + title band + row (cell height + gap))
///   sheet = gap + c (cell width + gap) wide (or the title's width plus 2 gap if wider),
///           gap + title band + rows (cell height + gap) tall.
/// Throws std::invalid_argument for columns < 1, gap < 0, label_scale < 1, a null image, or a
/// sheet too large for int sizes.
Image make_contact_sheet(std::span<const LabelledImage> cells, const SheetLayout& layout);

/// The w x h rectangle of `image` at (x, y) (clipped to the image). A rectangle entirely
/// outside (or w, h <= 0) gives an empty 0 x 0 image.
Image crop(const Image& image, int x, int y, int w, int h);

/// Each pixel repeated factor x factor times (nearest neighbour), to show noise up close.
/// Throws std::invalid_argument if factor < 1 or the result is too large for int sizes.
Image upscale_nearest(const Image& image, int factor);

}  // namespace mcrt
