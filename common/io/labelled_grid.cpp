#include "io/labelled_grid.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace mcrt {

Image labelled_grid(std::span<const Image> images, std::span<const std::string> labels, int factor,
                    const SheetLayout& layout) {
  if (images.size() != labels.size())
    throw std::invalid_argument("labelled_grid: one label per image");
  std::vector<Image> blown_up;
  blown_up.reserve(images.size());
  for (const Image& image : images) blown_up.push_back(upscale_nearest(image, factor));
  std::vector<LabelledImage> cells;
  for (std::size_t i = 0; i < blown_up.size(); ++i) cells.push_back({&blown_up[i], labels[i]});
  return make_contact_sheet(cells, layout);
}

Image block_means(const Image& image, int block) {
  if (block < 1) throw std::invalid_argument("block_means: block < 1");
  Image out(image.width, image.height);
  for (int y0 = 0; y0 < image.height; y0 += block)
    for (int x0 = 0; x0 < image.width; x0 += block) {
      const int y1 = std::min(image.height, y0 + block), x1 = std::min(image.width, x0 + block);
      Color sum(0.0);
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) sum += image.at(x, y);
      const Color mean = sum / static_cast<double>((y1 - y0) * (x1 - x0));
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) out.at(x, y) = mean;
    }
  return out;
}

Image centre_detail_strip(std::span<const Image> images, std::span<const std::string> labels,
                          std::string_view title_end, int block) {
  if (images.empty()) throw std::invalid_argument("centre_detail_strip: no images");
  if (images.size() != labels.size())
    throw std::invalid_argument("centre_detail_strip: one label per image");
  const int width = images.front().width, height = images.front().height;
  const int side = std::max(1, std::min(width, height) / 3);
  const int x = (width - side) / 2, y = (height - side) / 2;
  const int factor = std::max(1, 128 / side);
  std::vector<Image> details;
  std::vector<std::string> cell_labels(labels.begin(), labels.end());
  for (const Image& image : images) details.push_back(crop(image, x, y, side, side));
  if (block > 1)
    for (std::size_t i = 0; i < images.size(); ++i) {
      details.push_back(block_means(details[i], block));
      cell_labels.push_back(fmt::format("{}x{} means", block, block));
    }
  SheetLayout layout;
  layout.columns = static_cast<int>(images.size());
  layout.title =
      fmt::format("the image centre ({}x{} pixels, x{}) {}", side, side, factor, title_end);
  return labelled_grid(details, cell_labels, factor, layout);
}

}  // namespace mcrt
