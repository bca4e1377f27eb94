#pragma once
// Real 8-bit PNG files for the dataset tests, written with OpenImageIO.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/imageio.h>

// A size x size PNG whose stored value at (x, y, channel c) is value(x, y, c).
template <class Value>
void write_synthetic_png(const std::filesystem::path& path, int size, int channels, Value value) {
  std::filesystem::create_directories(path.parent_path());
  std::vector<uint8_t> pixels(static_cast<size_t>(size * size * channels));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      for (int c = 0; c < channels; ++c) pixels[static_cast<size_t>((y * size + x) * channels + c)] = value(x, y, c);
  OIIO::ImageSpec spec(size, size, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // values as given: a fourth channel is straight alpha
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out || !out->open(path.string(), spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
    throw std::runtime_error("cannot write " + path.string());
}
