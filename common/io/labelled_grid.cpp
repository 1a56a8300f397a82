#include "io/labelled_grid.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace mcrt {

Image labelled_grid(std::span<const Image> images, std::span<const std::string> labels,
                    int factor, const SheetLayout& layout) {
  if (images.size() != labels.size())
    throw std::invalid_argument("labelled_grid: one label per image");
  std::vector<Image> blown_up;
  blown_up.reserve(images.size());
  for (const Image& image : images) blown_up.push_back(upscale_nearest(image, factor));
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < blown_up.size(); ++i) cells.push_back({&blown_up[i], labels[i]});
  return make_contact_sheet(cells, layout);
}

Image centre_detail_strip(std::span<const Image> images, std::span<const std::string> labels,
                          std::string_view title_end) {
  if (images.empty()) throw std::invalid_argument("centre_detail_strip: no images");
  const int width = images.front().width, height = images.front().height;
  const int side = std::max(1, std::min(width, height) / 3);
  const int x = (width - side) / 2, y = (height - side) / 2;
  const int factor = std::max(1, 128 / side);
  std::vector<Image> details;
  for (const Image& image : images) details.push_back(crop(image, x, y, side, side));
  SheetLayout layout;
  layout.columns = static_cast<int>(details.size());
  layout.title = fmt::format("the image centre ({}x{} pixels, x{}) {}", side, side, factor, title_end);
  return labelled_grid(details, labels, factor, layout);
}

}  // namespace mcrt
