#include "io/contact_sheet.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "io/text.hpp"

namespace mcrt {

namespace {

// An image side computed in 64 bits, checked to fit the int that Image uses.
int checked_size(std::int64_t size, const char* what) {
  if (size > std::numeric_limits<int>::max())
    throw std::invalid_argument(std::string(what) + " too large: " + std::to_string(size) +
                                " pixels");
  return static_cast<int>(size);
}

// Copies `source` into `target` with its top-left corner at (x, y); the caller makes it fit.
void paste(Image& target, const Image& source, int x, int y) {
  for (int row = 0; row < source.height; ++row)
    std::copy_n(&source.at(0, row), source.width, &target.at(x, y + row));
}

}  // namespace

Image make_contact_sheet(std::span<const LabelledImage> cells, const SheetLayout& layout) {
  if (layout.columns < 1) throw std::invalid_argument("contact sheet: columns must be at least 1");
  if (layout.gap < 0) throw std::invalid_argument("contact sheet: gap must not be negative");
  if (layout.label_scale < 1)
    throw std::invalid_argument("contact sheet: label_scale must be at least 1");
  const int s = layout.label_scale;

  std::int64_t cell_width = 0, image_height = 0;
  bool any_label = false;
  for (const LabelledImage& cell : cells) {
    if (!cell.image) throw std::invalid_argument("contact sheet: a cell has no image");
    cell_width = std::max<std::int64_t>({cell_width, cell.image->width, text_width(cell.label, s)});
    image_height = std::max<std::int64_t>(image_height, cell.image->height);
    any_label = any_label || !cell.label.empty();
  }
  const std::int64_t count = static_cast<std::int64_t>(cells.size());
  const std::int64_t columns = std::min<std::int64_t>(layout.columns, count);
  const std::int64_t rows = columns == 0 ? 0 : (count + columns - 1) / columns;
  const std::int64_t gap = layout.gap;
  const std::int64_t band_height = any_label ? text_height(s) + 2 * std::int64_t{s} : 0;
  const std::int64_t cell_height = band_height + image_height;
  const std::int64_t title_band = layout.title.empty() ? 0 : text_height(s) + gap;

  const std::int64_t grid_width = gap + columns * (cell_width + gap);
  const std::int64_t title_width = layout.title.empty() ? 0 : 2 * gap + text_width(layout.title, s);
  Image sheet(checked_size(std::max(grid_width, title_width), "contact sheet width"),
              checked_size(gap + title_band + rows * (cell_height + gap), "contact sheet height"),
              layout.background);

  if (!layout.title.empty())
    draw_text(sheet, layout.gap, layout.gap, layout.title, layout.label_color, s);
  for (std::int64_t i = 0; i < count; ++i) {
    const LabelledImage& cell = cells[static_cast<std::size_t>(i)];
    // Every offset fits in int: it is smaller than the sheet size checked above.
    const int x = static_cast<int>(gap + (i % columns) * (cell_width + gap));
    const int y = static_cast<int>(gap + title_band + (i / columns) * (cell_height + gap));
    // The label is centred over its image, or starts at the cell's left edge if wider.
    const int label_x = x + std::max(0, (cell.image->width - text_width(cell.label, s)) / 2);
    draw_text(sheet, label_x, y + s, cell.label, layout.label_color, s);
    paste(sheet, *cell.image, x, y + static_cast<int>(band_height));
  }
  return sheet;
}

Image crop(const Image& image, int x, int y, int w, int h) {
  // Intersect [x, x + w) x [y, y + h) with the image, in 64 bits so x + w cannot overflow.
  const std::int64_t x0 = std::max(x, 0), y0 = std::max(y, 0);
  const std::int64_t x1 = std::min<std::int64_t>(std::int64_t{x} + w, image.width);
  const std::int64_t y1 = std::min<std::int64_t>(std::int64_t{y} + h, image.height);
  if (x1 <= x0 || y1 <= y0) return Image();
  Image result(static_cast<int>(x1 - x0), static_cast<int>(y1 - y0));
  for (int row = 0; row < result.height; ++row)
    std::copy_n(&image.at(static_cast<int>(x0), static_cast<int>(y0) + row), result.width,
                &result.at(0, row));
  return result;
}

Image upscale_nearest(const Image& image, int factor) {
  if (factor < 1)
    throw std::invalid_argument("upscale factor must be at least 1, got " + std::to_string(factor));
  Image result(checked_size(std::int64_t{image.width} * factor, "upscaled width"),
               checked_size(std::int64_t{image.height} * factor, "upscaled height"));
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x) result.at(x, y) = image.at(x / factor, y / factor);
  return result;
}

}  // namespace mcrt
