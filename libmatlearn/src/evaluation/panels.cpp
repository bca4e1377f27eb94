#include "matlearn/evaluation/panels.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "matbase/file/atomic_file.h"
#include "matbase/image/png_encoding.h"
#include "matbase/image/unorm.h"

namespace matlearn {
namespace {

// An 8-bit RGB canvas of tiles.
class Canvas {
 public:
  Canvas(int tiles_x, int tiles_y, int tile_width, int tile_height)
      : tile_width_(tile_width), tile_height_(tile_height), width_(tiles_x * tile_width),
        pixels_(static_cast<size_t>(width_) * static_cast<size_t>(tiles_y * tile_height) * 3, 0) {}

  // `image` at tile (x, y), values times `scale`, pixels off `mask` (when given) black.
  void put(int tile_x, int tile_y, const matbase::FloatImage& image, float scale, const matbase::Mask& mask = {}) {
    for (int y = 0; y < tile_height_; ++y)
      for (int x = 0; x < tile_width_; ++x) {
        const size_t pixel = static_cast<size_t>(y) * static_cast<size_t>(tile_width_) + static_cast<size_t>(x);
        const bool shown = mask.empty() || mask[pixel];
        for (int c = 0; c < 3; ++c) {
          const float v = shown ? image.at(x, y, std::min(c, image.channels - 1)) * scale : 0.0f;
          pixels_[(static_cast<size_t>(tile_y * tile_height_ + y) * static_cast<size_t>(width_) +
                   static_cast<size_t>(tile_x * tile_width_ + x)) * 3 + static_cast<size_t>(c)] =
              matbase::unorm8(v);
        }
      }
  }

  // Encoded in memory and written by the checked helper: a full disk is an error, not a
  // truncated panel (OpenImageIO's PNG writer reports no failed write).
  void write(const std::filesystem::path& path, matbase::AtomicFileSet* set) const {
    if (!path.parent_path().empty()) std::filesystem::create_directories(path.parent_path());
    matbase::ImagePixels image;
    image.name = path.string();
    image.width = width_;
    image.height = static_cast<int>(pixels_.size() / 3 / static_cast<size_t>(width_));
    image.channels = 3;
    image.data = pixels_;
    matbase::write_file_atomically(path, matbase::encode_png(image, path.string()), set);
  }

 private:
  int tile_width_, tile_height_, width_;
  std::vector<uint8_t> pixels_;
};

}  // namespace

void write_panel(const std::filesystem::path& path, const SamplePredictions& sample, matbase::AtomicFileSet* set) {
  const int rows = std::max<int>(1, static_cast<int>(sample.maps.size()));
  Canvas canvas(4, rows, sample.input.width, sample.input.height);
  canvas.put(0, 0, sample.input, 1.0f);
  for (size_t m = 0; m < sample.maps.size(); ++m) {
    const matbase::FloatImage& truth = sample.truths[m];
    const matbase::FloatImage& prediction = sample.predictions[m];
    matbase::FloatImage error(truth.width, truth.height, truth.channels);
    for (size_t i = 0; i < error.values.size(); ++i) error.values[i] = std::abs(truth.values[i] - prediction.values[i]);
    const int row = static_cast<int>(m);
    canvas.put(1, row, truth, 1.0f);
    canvas.put(2, row, prediction, 1.0f);
    canvas.put(3, row, error, 4.0f, sample.mask);
  }
  canvas.write(path, set);
}

void write_prediction_strip(const std::filesystem::path& path, const matbase::FloatImage& input, const matbase::Mask& mask,
                            const PredictedMaps& predicted, matbase::AtomicFileSet* set) {
  Canvas canvas(1 + static_cast<int>(predicted.maps.size()), 1, input.width, input.height);
  canvas.put(0, 0, input, 1.0f);
  for (size_t m = 0; m < predicted.maps.size(); ++m) canvas.put(1 + static_cast<int>(m), 0, predicted.maps[m], 1.0f, mask);
  canvas.write(path, set);
}

void write_map_png(const std::filesystem::path& path, const matbase::FloatImage& map, const matbase::Mask& mask,
                   matbase::AtomicFileSet* set) {
  Canvas canvas(1, 1, map.width, map.height);
  canvas.put(0, 0, map, 1.0f, mask);
  canvas.write(path, set);
}

}  // namespace matlearn
