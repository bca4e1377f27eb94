#include "matrender/image_io.h"

#include <cmath>
#include <filesystem>

#include "matbase/file/atomic_file.h"
#include "matbase/image/image_writing.h"

namespace matrender {
namespace fs = std::filesystem;

std::vector<std::string> write_frame(const FrameBuffers& frame, const std::string& folder, const std::string& stem,
                                     double exposure_stops) {
  matbase::OutputFolder output(folder);
  const int w = frame.width, h = frame.height;
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<std::string> written;
  auto file = [&](const std::string& pass, const std::string& ext) {
    return (fs::path(folder) / (stem + "_" + pass + "." + ext)).string();
  };
  // A view's files appear together or not at all.
  matbase::AtomicFileSet set(fs::path(folder) / stem);

  // Colour: RGBA EXR and display PNG. As with Cycles' film, alpha is the coverage only for a
  // transparent background; over an opaque background every pixel is opaque (A = 1).
  const bool with_alpha = frame.transparent_background && !frame.alpha.empty();
  std::vector<float> rgba(n * 4);
  for (size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) rgba[4 * i + c] = frame.color[3 * i + c];
    rgba[4 * i + 3] = with_alpha ? frame.alpha[i] : 1.0f;
  }
  written.push_back(file("color", "exr"));
  matbase::write_exr(written.back(), w, h, {"R", "G", "B", "A"}, rgba.data(), &set);
  written.push_back(file("color", "png"));
  matbase::write_display_png(written.back(), w, h, frame.color.data(), with_alpha ? frame.alpha.data() : nullptr,
                    exposure_stops, &set);

  auto write_float_pass = [&](const std::string& pass, const std::vector<float>& data, int channels,
                              const std::vector<std::string>& names, double png_scale, double png_offset) {
    if (data.empty()) return;
    written.push_back(file(pass, "exr"));
    matbase::write_exr(written.back(), w, h, names, data.data(), &set);
    written.push_back(file(pass, "png"));
    matbase::write_data_png(written.back(), w, h, channels, data.data(), png_scale, png_offset, false, &set);
  };
  // Material parameters, named as in the table. Colours are linear like the renderer's inputs;
  // their PNG stores sRGB-encoded values for viewing. A scalar's PNG maps its range to 0..255.
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters) {
    const std::vector<float>& values = frame.parameter(info.id);
    if (values.empty()) continue;
    if (info.kind == matmaterial::ParameterKind::Color) {
      written.push_back(file(info.name, "exr"));
      matbase::write_exr(written.back(), w, h, {"R", "G", "B"}, values.data(), &set);
      written.push_back(file(info.name, "png"));
      matbase::write_display_png(written.back(), w, h, values.data(), nullptr, 0.0, &set);
    } else {
      const double scale = 255.0 / (info.max - info.min);
      write_float_pass(info.name, values, 1, {"Y"}, scale, -info.min * scale);
    }
  }
  write_float_pass("normal_world", frame.normal_world, 3, {"X", "Y", "Z"}, 127.5, 127.5);
  write_float_pass("normal_camera", frame.normal_camera, 3, {"X", "Y", "Z"}, 127.5, 127.5);
  write_float_pass("normal_tangent", frame.normal_tangent, 3, {"X", "Y", "Z"}, 127.5, 127.5);
  write_float_pass("ambient_occlusion", frame.ambient_occlusion, 1, {"Y"}, 255.0, 0.0);
  // The PNG shows the standard error (its square root) on the colour's scale: 1 is white.
  if (!frame.color_variance.empty()) {
    std::vector<float> standard_error(frame.color_variance.size());
    for (size_t k = 0; k < standard_error.size(); ++k) standard_error[k] = std::sqrt(frame.color_variance[k]);
    written.push_back(file("color_variance", "exr"));
    matbase::write_exr(written.back(), w, h, {"Y"}, frame.color_variance.data(), &set);
    written.push_back(file("color_variance", "png"));
    matbase::write_data_png(written.back(), w, h, 1, standard_error.data(), 255.0, 0.0, false, &set);
  }
  if (!frame.depth.empty()) {
    written.push_back(file("depth", "exr"));
    matbase::write_exr(written.back(), w, h, {"Z"}, frame.depth.data(), &set);
    // 16-bit PNG in millimetres (0 = background), as depth cameras write.
    written.push_back(file("depth", "png"));
    matbase::write_data_png(written.back(), w, h, 1, frame.depth.data(), 1000.0, 0.0, true, &set);
  }
  auto write_id_pass = [&](const std::string& pass, const std::vector<int32_t>& ids, double offset) {
    if (ids.empty()) return;
    std::vector<float> values(ids.begin(), ids.end());
    written.push_back(file(pass, "exr"));
    matbase::write_exr(written.back(), w, h, {"Y"}, values.data(), &set);
    written.push_back(file(pass, "png"));
    matbase::write_data_png(written.back(), w, h, 1, values.data(), 1.0, offset, true, &set);
  };
  write_id_pass("label", frame.label, 0.0);
  write_id_pass("part_id", frame.part_id, 1.0);  // PNG value = part id + 1, 0 = background
  write_id_pass("object_id", frame.object_id, 1.0);
  write_id_pass("sample_count", frame.sample_count, 0.0);
  if (!frame.alpha.empty()) {
    written.push_back(file("alpha", "png"));
    matbase::write_data_png(written.back(), w, h, 1, frame.alpha.data(), 255.0, 0.0, false, &set);
  }
  set.commit();
  output.keep();
  return written;
}

}  // namespace matrender
