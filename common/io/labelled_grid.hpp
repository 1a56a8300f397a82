#pragma once
/// The two figures the rendering chapters make from several renders, built on contact sheets:
/// a grid of whole images and a strip of one detail of each, both blown up without smoothing
/// so the noise stays visible, each image under its label.

#include <span>
#include <string>
#include <string_view>

#include "io/contact_sheet.hpp"
#include "render/image.hpp"

namespace mcrt {

/// The images, each blown up `factor` times (nearest neighbour), in a contact sheet laid out
/// by `layout`, image i under labels[i]. Throws std::invalid_argument if the counts differ.
Image labelled_grid(std::span<const Image> images, std::span<const std::string> labels, int factor,
                    const SheetLayout& layout);

/// The same detail of every image side by side: the centred square a third of the shorter
/// side wide, blown up to about 128 pixels, under labels[i]. The title names the detail, its
/// size and scale, and ends with `title_end` (e.g. "at growing spp").
///
/// With block > 1, a second row shows each detail with every block x block square replaced by
/// its mean: the light that sparse bright pixels carry, spread over their neighbours. At low
/// spp the first row is mostly black, yet the second already has the right brightness (the
/// estimate is unbiased); its blotches fade as spp grows.
Image centre_detail_strip(std::span<const Image> images, std::span<const std::string> labels,
                          std::string_view title_end, int block = 0);

/// Every block x block square of `image` (the last ones clipped) set to its mean.
/// Throws std::invalid_argument if block < 1.
Image block_means(const Image& image, int block);

}  // namespace mcrt
