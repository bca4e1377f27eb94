#include "matdataset/format/texture_target_writer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "matbase/file/atomic_file.h"
#include "matbase/image/image_writing.h"
#include "matbase/image/object_crop.h"
#include "matbase/image/png_encoding.h"
#include "matdataset/format/decoded_image.h"

namespace matdataset {
namespace {

namespace fs = std::filesystem;

void write_reference(const fs::path& path, const matbase::ImagePixels& image) {
  if (!matbase::is_well_formed(image))
    throw std::invalid_argument(path.string() + ": the reference image's size and bytes disagree");
  fs::create_directories(path.parent_path());
  matbase::write_file_atomically(path, matbase::encode_png(image, path.string()));
}

}  // namespace

void write_texture_target_references(const fs::path& root, const std::string& material,
                                     const MaterialReferences& references) {
  write_reference(root / "ground_truth_basecolour" / (material + ".png"), references.base_color);
  write_reference(root / "ground_truth_roughness" / (material + ".png"), references.roughness);
  write_reference(root / "ground_truth_metallic" / (material + ".png"), references.metallic);
  if (references.normal) write_reference(root / "ground_truth_normal" / (material + ".png"), *references.normal);
}

fs::path texture_target_screenshot_path(const fs::path& root, const std::string& object, const std::string& material,
                                        const std::string& stem) {
  return root / "rendered_cropped" / object / material / (stem + ".png");
}

void write_texture_target_screenshot(const fs::path& root, const std::string& object, const std::string& material,
                                     const std::string& stem, const FrameMaps& maps) {
  const int w = maps.width, h = maps.height;
  if (w <= 0 || h <= 0 || maps.coverage.size() != static_cast<size_t>(w) * static_cast<size_t>(h) ||
      maps.color.size() != 3 * maps.coverage.size())
    throw std::invalid_argument("screenshot: the frame's colour and coverage do not match its size");
  matbase::Mask covered(maps.coverage.size());
  for (size_t p = 0; p < covered.size(); ++p) covered[p] = maps.coverage[p] > 0.0f;
  const matbase::CropSquare square =
      matbase::object_crop_square(matbase::mask_bounds(covered, w, h).value_or(matbase::PixelBox{0, 0, w - 1, h - 1}));
  const int side = square.side, left = square.left, top = square.top;
  const float gain = static_cast<float>(std::exp2(maps.exposure_stops));
  std::vector<float> rgb(3 * static_cast<size_t>(side) * static_cast<size_t>(side), 1.0f);  // white
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const int sx = left + x, sy = top + y;
      if (sx < 0 || sy < 0 || sx >= w || sy >= h) continue;
      const size_t p = static_cast<size_t>(sy) * static_cast<size_t>(w) + static_cast<size_t>(sx);
      const size_t q = static_cast<size_t>(y) * static_cast<size_t>(side) + static_cast<size_t>(x);
      // Colour is premultiplied by coverage: over white, in linear light.
      for (size_t c = 0; c < 3; ++c) rgb[3 * q + c] = maps.color[3 * p + c] * gain + (1.0f - maps.coverage[p]);
    }
  const fs::path path = texture_target_screenshot_path(root, object, material, stem);
  fs::create_directories(path.parent_path());
  matbase::write_display_png(path.string(), side, side, rgb.data(), nullptr);
}

bool texture_target_screenshot_is_complete(const fs::path& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return false;
  try {
    decode(path);
    return true;
  } catch (const std::runtime_error&) {
    return false;
  }
}

}  // namespace matdataset
