#pragma once
// The square the paper's preprocessing crops an object to before a network sees it: the object's
// bounding box, centred, its longer side grown by 4 % on each side (at least 2 pixels), so that
// the silhouette never touches the crop's border. One rule for the paper's texture-target
// screenshots (matdataset) and for isolating an object in a photograph (matlearn/isolation).
#include <cstdint>
#include <optional>
#include <vector>

#include "matbase/image/float_image.h"

namespace matbase {

// Pixels from (x0, y0) to (x1, y1), both included: column x, row y from the top-left.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};

// A square of `side` pixels whose top-left pixel is (left, top); it may reach past the image.
struct CropSquare {
  int left = 0, top = 0, side = 0;
};

// The smallest box around the nonzero entries of a width x height mask; none when all are zero.
std::optional<PixelBox> mask_bounds(const Mask& mask, int width, int height);

// The square around `box` by the rule above.
CropSquare object_crop_square(const PixelBox& box);

// The pixels of `image` inside `square`, with `background` (one value per channel) where the
// square reaches past the image and, when `mask` is not empty, where the mask is zero.
FloatImage crop_to_square(const FloatImage& image, const CropSquare& square, const std::vector<float>& background,
                          const Mask& mask = {});

}  // namespace matbase
