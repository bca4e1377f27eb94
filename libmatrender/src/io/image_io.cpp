#include "matrender/image_io.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "matgeom/atomic_file.h"
#include "matgeom/srgb.h"
#include "matgeom/unorm.h"

namespace matrender {
namespace {

namespace fs = std::filesystem;

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
               const float* data, matgeom::AtomicFileSet* set) {
  OIIO::ImageSpec spec(width, height, static_cast<int>(channels.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = channels;
  spec.alpha_channel = -1;
  for (size_t c = 0; c < channels.size(); ++c)
    if (channels[c] == "A") spec.alpha_channel = static_cast<int>(c);
  spec.attribute("compression", "zip");
  matgeom::write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::FLOAT, data), set);
}

void write_display_png(const std::string& path, int width, int height, const float* rgb, const float* alpha,
                       double exposure_stops, matgeom::AtomicFileSet* set) {
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
      pixels[i * channels + c] = matgeom::unorm8(matgeom::linear_to_srgb(std::clamp(linear, 0.0f, 1.0f)));
    }
    if (alpha) pixels[i * channels + 3] = matgeom::unorm8(alpha[i]);
  }
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // already straight: OpenImageIO must not divide again
  matgeom::write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::UINT8, pixels.data()), set);
}

void write_data_png(const std::string& path, int width, int height, int channels, const float* data, double scale,
                    double offset, bool sixteen_bit, matgeom::AtomicFileSet* set) {
  const size_t n = static_cast<size_t>(width) * height * channels;
  std::vector<uint16_t> pixels(n);
  const double max_value = sixteen_bit ? 65535.0 : 255.0;
  for (size_t i = 0; i < n; ++i) pixels[i] = matgeom::unorm_code((data[i] * scale + offset) / max_value, static_cast<uint16_t>(max_value));
  OIIO::ImageSpec spec(width, height, channels, sixteen_bit ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:UnassociatedAlpha", 1);  // a fourth channel is data: written verbatim
  if (sixteen_bit) {
    matgeom::write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::UINT16, pixels.data()), set);
  } else {
    std::vector<uint8_t> narrow(pixels.begin(), pixels.end());
    matgeom::write_file_atomically(path, encode_image(path, spec, OIIO::TypeDesc::UINT8, narrow.data()), set);
  }
}

std::vector<std::string> write_frame(const FrameBuffers& frame, const std::string& folder, const std::string& stem,
                                     double exposure_stops) {
  matgeom::OutputFolder output(folder);
  const int w = frame.width, h = frame.height;
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<std::string> written;
  auto file = [&](const std::string& pass, const std::string& ext) {
    return (fs::path(folder) / (stem + "_" + pass + "." + ext)).string();
  };
  // A view's files appear together or not at all.
  matgeom::AtomicFileSet set(fs::path(folder) / stem);

  // Colour: RGBA EXR and display PNG. As with Cycles' film, alpha is the coverage only for a
  // transparent background; over an opaque background every pixel is opaque (A = 1).
  const bool with_alpha = frame.transparent_background && !frame.alpha.empty();
  std::vector<float> rgba(n * 4);
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = frame.color[3 * i + c];
    rgba[4 * i + 3] = with_alpha ? frame.alpha[i] : 1.0f;
  }
  written.push_back(file("color", "exr"));
  write_exr(written.back(), w, h, {"R", "G", "B", "A"}, rgba.data(), &set);
  written.push_back(file("color", "png"));
  write_display_png(written.back(), w, h, frame.color.data(), with_alpha ? frame.alpha.data() : nullptr,
                    exposure_stops, &set);

  auto write_float_pass = [&](const std::string& pass, const std::vector<float>& data, int channels,
                              const std::vector<std::string>& names, double png_scale, double png_offset) {
    if (data.empty()) return;
    written.push_back(file(pass, "exr"));
    write_exr(written.back(), w, h, names, data.data(), &set);
    written.push_back(file(pass, "png"));
    write_data_png(written.back(), w, h, channels, data.data(), png_scale, png_offset, false, &set);
  };
  // Material parameters, named as in the table. Colours are linear like the renderer's inputs;
  // their PNG stores sRGB-encoded values for viewing. A scalar's PNG maps its range to 0..255.
  for (const matgeom::MaterialParameterInfo& info : matgeom::kMaterialParameters) {
    const std::vector<float>& values = frame.parameter(info.id);
    if (values.empty()) continue;
    if (info.kind == matgeom::ParameterKind::Color) {
      written.push_back(file(info.name, "exr"));
      write_exr(written.back(), w, h, {"R", "G", "B"}, values.data(), &set);
      written.push_back(file(info.name, "png"));
      write_display_png(written.back(), w, h, values.data(), nullptr, 0.0, &set);
    } else {
      const double scale = 255.0 / (info.max - info.min);
      write_float_pass(info.name, values, 1, {"Y"}, scale, -info.min * scale);
    }
  }
  write_float_pass("normal_world", frame.normal_world, 3, {"X", "Y", "Z"}, 127.5, 127.5);
  write_float_pass("normal_camera", frame.normal_camera, 3, {"X", "Y", "Z"}, 127.5, 127.5);
  write_float_pass("normal_tangent", frame.normal_tangent, 3, {"X", "Y", "Z"}, 127.5, 127.5);
  write_float_pass("ambient_occlusion", frame.ambient_occlusion, 1, {"Y"}, 255.0, 0.0);
  if (!frame.depth.empty()) {
    written.push_back(file("depth", "exr"));
    write_exr(written.back(), w, h, {"Z"}, frame.depth.data(), &set);
    // 16-bit PNG in millimetres (0 = background), as depth cameras write.
    written.push_back(file("depth", "png"));
    write_data_png(written.back(), w, h, 1, frame.depth.data(), 1000.0, 0.0, true, &set);
  }
  auto write_id_pass = [&](const std::string& pass, const std::vector<int32_t>& ids, double offset) {
    if (ids.empty()) return;
    std::vector<float> values(ids.begin(), ids.end());
    written.push_back(file(pass, "exr"));
    write_exr(written.back(), w, h, {"Y"}, values.data(), &set);
    written.push_back(file(pass, "png"));
    write_data_png(written.back(), w, h, 1, values.data(), 1.0, offset, true, &set);
  };
  write_id_pass("label", frame.label, 0.0);
  write_id_pass("part_id", frame.part_id, 1.0);  // PNG value = part id + 1, 0 = background
  if (!frame.alpha.empty()) {
    written.push_back(file("alpha", "png"));
    write_data_png(written.back(), w, h, 1, frame.alpha.data(), 255.0, 0.0, false, &set);
  }
  set.commit();
  output.keep();
  return written;
}

}  // namespace matrender
