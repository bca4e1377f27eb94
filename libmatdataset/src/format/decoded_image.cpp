#include "matdataset/format/decoded_image.h"

#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include <OpenImageIO/imageio.h>

#include "matbase/file/input_file.h"
#include "matbase/image/image_header.h"
#include "matbase/memory_limit.h"
#include "matdataset/format/dataset_error.h"

namespace matdataset {
namespace {

std::string size_text(int width, int height) { return std::to_string(width) + "x" + std::to_string(height); }

// The file opened for reading, once it is known to be a regular file whose declared pixels
// (`channels` of `bytes_per_value` each) fit in memory.
std::unique_ptr<OIIO::ImageInput> open_image(const std::filesystem::path& path, double bytes_per_value) {
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in;
  try {
    matbase::require_input_file(path.string());
    if (const std::optional<std::string> problem = matbase::declared_size_problem(path))
      throw DatasetError(path.string() + ": " + *problem);
    in = OIIO::ImageInput::open(path.string(), &config);
    if (!in) throw DatasetError("cannot read " + path.string() + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    const double values = static_cast<double>(spec.width) * static_cast<double>(spec.height) *
                          static_cast<double>(spec.nchannels);
    matbase::require_memory(values * bytes_per_value,
                            "decoding its " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
                                " pixels",
                            path.string());
  } catch (const DatasetError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw DatasetError(e.what());  // matbase's sentences already name the file
  }
  return in;
}

size_t value_count(const OIIO::ImageSpec& spec) {
  return static_cast<size_t>(spec.width) * static_cast<size_t>(spec.height) * static_cast<size_t>(spec.nchannels);
}

}  // namespace

matbase::FloatImage decode(const std::filesystem::path& path) {
  const std::unique_ptr<OIIO::ImageInput> in = open_image(path, sizeof(float));
  const OIIO::ImageSpec& spec = in->spec();
  matbase::FloatImage d(spec.width, spec.height, spec.nchannels);
  if (!in->read_image(0, 0, 0, d.channels, OIIO::TypeDesc::FLOAT, d.values.data()))
    throw DatasetError("cannot decode " + path.string() + ": " + in->geterror());
  return d;
}

matbase::FloatImage decode_finite(const std::filesystem::path& path) {
  matbase::FloatImage d = decode(path);
  for (size_t i = 0; i < d.values.size(); ++i)
    if (!std::isfinite(d.values[i])) {
      const size_t pixel = i / static_cast<size_t>(d.channels);
      throw DatasetError(path.string() + ": channel " + std::to_string(i % static_cast<size_t>(d.channels)) +
                         " of pixel (" + std::to_string(pixel % static_cast<size_t>(d.width)) + ", " +
                         std::to_string(pixel / static_cast<size_t>(d.width)) + ") is " +
                         std::to_string(d.values[i]) + ", not a finite number");
    }
  return d;
}

DecodedIds decode_ids(const std::filesystem::path& path) {
  const std::unique_ptr<OIIO::ImageInput> in = open_image(path, sizeof(int32_t));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels != 1)
    throw DatasetError(path.string() + " has " + std::to_string(spec.nchannels) +
                       " channels; a label map has one, the id of each pixel");
  // PNG's 1-, 2- and 4-bit grey are widened to 8 bits by scaling, which would change the ids.
  const int bits = spec.get_int_attribute("oiio:BitsPerSample", static_cast<int>(spec.format.size() * 8));
  const bool integers = spec.format == OIIO::TypeDesc::UINT8 || spec.format == OIIO::TypeDesc::UINT16;
  if (!integers || bits != static_cast<int>(spec.format.size() * 8))
    throw DatasetError(path.string() + " stores " + std::to_string(bits) + "-bit " + spec.format.c_str() +
                       " values; a label map holds 8- or 16-bit unsigned integer ids");
  DecodedIds d{spec.width, spec.height, std::vector<int32_t>(value_count(spec))};
  // Read in the file's own format: asking for another one would rescale the ids.
  std::vector<uint16_t> wide(spec.format == OIIO::TypeDesc::UINT16 ? d.ids.size() : 0);
  std::vector<uint8_t> narrow(spec.format == OIIO::TypeDesc::UINT8 ? d.ids.size() : 0);
  void* buffer = wide.empty() ? static_cast<void*>(narrow.data()) : static_cast<void*>(wide.data());
  if (!in->read_image(0, 0, 0, 1, spec.format, buffer))
    throw DatasetError("cannot decode " + path.string() + ": " + in->geterror());
  for (size_t p = 0; p < d.ids.size(); ++p) d.ids[p] = wide.empty() ? narrow[p] : wide[p];
  return d;
}

matbase::FloatImage channels_of(const matbase::FloatImage& d, int first, int channels) {
  matbase::FloatImage image(d.width, d.height, channels);
  for (size_t p = 0; p < image.pixel_count(); ++p)
    for (int c = 0; c < channels; ++c)
      image.values[p * static_cast<size_t>(channels) + static_cast<size_t>(c)] =
          d.values[p * static_cast<size_t>(d.channels) + static_cast<size_t>(d.channels >= first + channels ? first + c : 0)];
  return image;
}

void check_same_size(int width, int height, const matbase::FloatImage& image, const std::filesystem::path& path) {
  if (width != image.width || height != image.height)
    throw DatasetError(path.string() + " is " + size_text(width, height) + " but the sample's image is " +
                       size_text(image.width, image.height));
}

void check_channels(const matbase::FloatImage& d, int channels, const char* what, const std::filesystem::path& path) {
  if (d.channels < channels)
    throw DatasetError(path.string() + " has " + std::to_string(d.channels) + " channel" + (d.channels == 1 ? "" : "s") +
                       ", not the " + std::to_string(channels) + " that hold " + what);
}

}  // namespace matdataset
