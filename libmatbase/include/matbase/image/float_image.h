#pragma once
// The image type the metrics and the dataset code share: plain float values, rows of pixels with
// their channels interleaved (HWC, the layout of OpenImageIO's and numpy's arrays).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace matbase {

struct FloatImage {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> values;  // width * height * channels

  FloatImage() = default;
  FloatImage(int width_, int height_, int channels_, float fill = 0.0f)
      : width(width_), height(height_), channels(channels_),
        values(static_cast<size_t>(width_) * static_cast<size_t>(height_) * static_cast<size_t>(channels_), fill) {}

  size_t pixel_count() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
  float& at(int x, int y, int c) { return values[index(x, y, c)]; }
  float at(int x, int y, int c) const { return values[index(x, y, c)]; }

 private:
  size_t index(int x, int y, int c) const {
    return (static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) *
               static_cast<size_t>(channels) + static_cast<size_t>(c);
  }
};

// Which pixels an evaluation covers: one entry per pixel in row order, nonzero = inside (the
// object). An empty mask covers every pixel.
using Mask = std::vector<uint8_t>;

}  // namespace matbase
