#pragma once
// The checks every metric makes before it reads a pixel, and the mask test they share.
#include <cstddef>

#include "matbase/image/float_image.h"

namespace matlearn {

// Throws std::invalid_argument, naming `metric`, unless truth and prediction are non-empty with
// equal width, height and channels, the mask is empty or has one entry per pixel, and it covers
// at least one pixel.
void check_image_pair(const char* metric, const matbase::FloatImage& truth, const matbase::FloatImage& prediction, const matbase::Mask& mask);

// Throws std::invalid_argument unless data_range is finite and positive.
void check_data_range(const char* metric, double data_range);

inline bool inside(const matbase::Mask& mask, size_t pixel) { return mask.empty() || mask[pixel] != 0; }

}  // namespace matlearn
