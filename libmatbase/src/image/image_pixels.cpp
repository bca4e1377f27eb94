#include "matbase/image/image_pixels.h"

#include <utility>

namespace matbase {

ImagePixels blank_image(std::string name, int width, int height, int channels) {
  ImagePixels image;
  image.name = std::move(name);
  image.width = width;
  image.height = height;
  image.channels = channels;
  image.data.resize(static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(channels));
  return image;
}

bool is_well_formed(const ImagePixels& image) {
  return image.width > 0 && image.height > 0 && image.channels >= 1 && image.channels <= 4 &&
         image.data.size() == static_cast<size_t>(image.width) * static_cast<size_t>(image.height) *
                                  static_cast<size_t>(image.channels);
}

uint8_t texel_channel(const ImagePixels& image, size_t texel, int channel) {
  const bool grey = image.channels < 3;
  const bool has_alpha = image.channels == 2 || image.channels == 4;
  const size_t first = texel * static_cast<size_t>(image.channels);
  if (channel == 3) return has_alpha ? image.data[first + static_cast<size_t>(image.channels) - 1] : 255;
  return image.data[first + (grey ? 0 : static_cast<size_t>(channel))];
}

}  // namespace matbase
