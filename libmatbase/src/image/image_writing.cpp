#include "matbase/image/image_writing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "matbase/image/srgb.h"
#include "matbase/image/unorm.h"

namespace matbase {
namespace {

// The image encoded in memory, in the format of `path`'s extension. Encoding to memory and then
// writing the bytes with the checked helpers is what makes a full disk an error: OpenImageIO's PNG
// writer reports no failed write and leaves a truncated file.
std::string encode_image(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                         const void* pixels) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto output = OIIO::ImageOutput::create(path, &memory);
  if (!output) throw std::runtime_error(path + ": no image writer for this extension: " + OIIO::geterror());
  if (!output->supports("ioproxy")) throw std::runtime_error(path + ": the image writer cannot encode to memory");
  if (!output->open(path, spec)) throw std::runtime_error(path + ": cannot encode: " + output->geterror());
  const bool written = output->write_image(type, pixels);
  const std::string write_error = written ? "" : output->geterror();
  const bool closed = output->close();
  if (!written) throw std::runtime_error(path + ": cannot encode the image: " + write_error);
  if (!closed) throw std::runtime_error(path + ": cannot finish encoding the image: " + output->geterror());
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

void write_exr(const std::string& path, int width, int height, const std::vector<std::string>& channels,
               const float* data, AtomicFileSet* set) {
  OIIO::ImageSpec spec(width, height, static_cast<int>(channels.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = channels;
  spec.alpha_channel = -1;
  for (size_t c = 0; c < channels.size(); ++c)
    if (channels[c] == "A") spec.alpha_channel = static_cast<int>(c);
  spec.attribute("compression", "zip");
  // OpenImageIO stamps an EXR with the time it was written unless told a DateTime: an empty one
  // keeps the bytes of a file the same on every run.
  spec.attribute("DateTime", "");
  write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::FLOAT, data), set);
}

uint8_t display_code(float linear) { return unorm8(linear_to_srgb(std::clamp(linear, 0.0f, 1.0f))); }

void write_display_png(const std::string& path, int width, int height, const float* rgb, const float* alpha,
                       double exposure_stops, AtomicFileSet* set) {
  const int channels = alpha ? 4 : 3;
  const double gain = std::exp2(exposure_stops);
  std::vector<uint8_t> pixels(static_cast<size_t>(width) * height * channels);
  for (size_t i = 0; i < static_cast<size_t>(width) * height; ++i) {
    // PNG stores straight alpha: un-premultiply in linear space, then encode, so partly covered
    // pixels keep the surface's colour instead of a darkened or haloed one.
    const float coverage = alpha ? alpha[i] : 1.0f;
    const double unpremultiply = coverage > 0.0f ? gain / coverage : gain;
    for (int c = 0; c < 3; ++c) {
      const float linear = static_cast<float>(rgb[3 * i + c] * unpremultiply);
      pixels[i * channels + c] = display_code(linear);
    }
    if (alpha) pixels[i * channels + 3] = unorm8(alpha[i]);
  }
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // already straight: OpenImageIO must not divide again
  write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::UINT8, pixels.data()), set);
}

void write_data_png(const std::string& path, int width, int height, int channels, const float* data, double scale,
                    double offset, bool sixteen_bit, AtomicFileSet* set) {
  const size_t n = static_cast<size_t>(width) * height * channels;
  std::vector<uint16_t> pixels(n);
  const double max_value = sixteen_bit ? 65535.0 : 255.0;
  for (size_t i = 0; i < n; ++i) pixels[i] = unorm_code((data[i] * scale + offset) / max_value, static_cast<uint16_t>(max_value));
  OIIO::ImageSpec spec(width, height, channels, sixteen_bit ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // a fourth channel is data: written verbatim
  if (sixteen_bit) {
    write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::UINT16, pixels.data()), set);
  } else {
    std::vector<uint8_t> narrow(pixels.begin(), pixels.end());
    write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::UINT8, narrow.data()), set);
  }
}

}  // namespace matbase
