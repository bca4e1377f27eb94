#include "matlearn/decoded_image.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <OpenImageIO/imageio.h>

#include "matgeom/input_file.h"
#include "matgeom/memory_limit.h"

namespace matlearn {

Decoded decode(const std::filesystem::path& path) {
  matgeom::require_input_file(path.string());
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) throw std::runtime_error("cannot read " + path.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Decoded d{spec.width, spec.height, spec.nchannels, {}};
  const double values = static_cast<double>(d.width) * static_cast<double>(d.height) * static_cast<double>(d.channels);
  matgeom::require_memory(values * sizeof(float),
                          "decoding its " + std::to_string(d.width) + " x " + std::to_string(d.height) + " pixels",
                          path.string());
  d.values.resize(static_cast<size_t>(d.width) * static_cast<size_t>(d.height) * static_cast<size_t>(d.channels));
  if (!in->read_image(0, 0, 0, d.channels, OIIO::TypeDesc::FLOAT, d.values.data()))
    throw std::runtime_error("cannot decode " + path.string() + ": " + in->geterror());
  return d;
}

Image channels_of(const Decoded& d, int first, int channels) {
  Image image(d.width, d.height, channels);
  for (size_t p = 0; p < image.pixel_count(); ++p)
    for (int c = 0; c < channels; ++c)
      image.values[p * static_cast<size_t>(channels) + static_cast<size_t>(c)] =
          d.values[p * static_cast<size_t>(d.channels) + static_cast<size_t>(d.channels >= first + channels ? first + c : 0)];
  return image;
}


void check_same_size(const Decoded& d, const Decoded& image, const std::filesystem::path& path) {
  if (d.width != image.width || d.height != image.height)
    throw std::runtime_error(path.string() + " is " + std::to_string(d.width) + "x" + std::to_string(d.height) +
                             " but the sample's image is " + std::to_string(image.width) + "x" +
                             std::to_string(image.height));
}

}  // namespace matlearn
