#include "matbase/image/object_crop.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace matbase {

std::optional<PixelBox> mask_bounds(const Mask& mask, int width, int height) {
  if (mask.size() != static_cast<size_t>(width) * static_cast<size_t>(height))
    throw std::invalid_argument("mask_bounds: the mask does not have width x height entries");
  PixelBox box{width, height, -1, -1};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (mask[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)] != 0)
        box = {std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x), std::max(box.y1, y)};
  if (box.x1 < 0) return std::nullopt;
  return box;
}

CropSquare object_crop_square(const PixelBox& box) {
  const int extent = std::max(box.width(), box.height());
  const int side = extent + 2 * std::max(2, static_cast<int>(std::lround(0.04 * extent)));
  return {(box.x0 + box.x1 + 1 - side) / 2, (box.y0 + box.y1 + 1 - side) / 2, side};
}

FloatImage crop_to_square(const FloatImage& image, const CropSquare& square, const std::vector<float>& background,
                          const Mask& mask) {
  if (background.size() != static_cast<size_t>(image.channels))
    throw std::invalid_argument("crop_to_square: the background needs one value per channel");
  if (!mask.empty() && mask.size() != image.pixel_count())
    throw std::invalid_argument("crop_to_square: the mask does not have one entry per pixel");
  FloatImage crop(square.side, square.side, image.channels);
  for (int y = 0; y < square.side; ++y)
    for (int x = 0; x < square.side; ++x) {
      const int sx = square.left + x, sy = square.top + y;
      const bool inside = sx >= 0 && sy >= 0 && sx < image.width && sy < image.height &&
                          (mask.empty() || mask[static_cast<size_t>(sy) * static_cast<size_t>(image.width) +
                                                static_cast<size_t>(sx)] != 0);
      for (int c = 0; c < image.channels; ++c)
        crop.at(x, y, c) = inside ? image.at(sx, sy, c) : background[static_cast<size_t>(c)];
    }
  return crop;
}

}  // namespace matbase
