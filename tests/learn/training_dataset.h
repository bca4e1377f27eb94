#pragma once
// The four-image dataset the training and evaluation tests share, in the MatPredict layout as
// real PNG files: sample k (0..3) in object_<k % 2>/var00<k / 2> is a disc whose colour, albedo,
// roughness and normal depend on k (far from an untrained network's 0.5), label k % 3 + 1 on it.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>

#include "matdataset/format/dataset_index.h"
#include "matlearn/training/trainer.h"
#include "support/synthetic_png.h"

namespace training_dataset {

constexpr int kSize = 32;
constexpr uint8_t kAlbedo[4][3] = {{230, 20, 20}, {20, 230, 20}, {20, 20, 230}, {230, 230, 20}};
constexpr uint8_t kRoughness[4] = {25, 230, 25, 230};

// Sample k's normal, (sin t, 0, cos t) with t = 0.4 k radians, stored as 8-bit 0.5 n + 0.5.
inline uint8_t encoded_normal(int k, int c) {
  const double n[3] = {std::sin(0.4 * k), 0.0, std::cos(0.4 * k)};
  return static_cast<uint8_t>(std::lround(255.0 * (0.5 * n[c] + 0.5)));
}

inline bool inside_disc(int x, int y) { return (x - 15.5) * (x - 15.5) + (y - 15.5) * (y - 15.5) < 120.0; }

inline int sample_index(const matdataset::SampleId& id) {
  return 2 * (id.variant.back() - '0') + (id.object.back() - '0');
}

inline void write_sample(const std::filesystem::path& root, int k) {
  const std::filesystem::path variant = root / ("object_" + std::to_string(k % 2)) / ("var00" + std::to_string(k / 2));
  write_synthetic_png(variant / "images" / "000.png", kSize, 4, [&](int x, int y, int c) -> uint8_t {
    if (!inside_disc(x, y)) return 0;
    return c == 3 ? 255 : static_cast<uint8_t>(kAlbedo[k][c] * 0.6 * (kRoughness[k] > 100 ? 0.7 : 1.0));
  });
  write_synthetic_png(variant / "albedo" / "000.png", kSize, 4, [&](int x, int y, int c) -> uint8_t {
    return inside_disc(x, y) ? (c == 3 ? 255 : kAlbedo[k][c]) : 0;
  });
  write_synthetic_png(variant / "ORM" / "000.png", kSize, 4, [&](int x, int y, int c) -> uint8_t {
    const uint8_t orm[4] = {255, kRoughness[k], 0, 255};
    return inside_disc(x, y) ? orm[c] : 0;
  });
  write_synthetic_png(variant / "normal_obj" / "000.png", kSize, 4, [&](int x, int y, int c) -> uint8_t {
    return inside_disc(x, y) ? (c == 3 ? 255 : encoded_normal(k, c)) : 0;
  });
  write_synthetic_png(variant / "label" / "000.png", kSize, 1, [&](int x, int y, int) -> uint8_t {
    return inside_disc(x, y) ? static_cast<uint8_t>(k % 3 + 1) : 0;
  });
}

inline std::filesystem::path four_image_dataset() {
  static const std::filesystem::path root = [] {
    const std::filesystem::path r = std::filesystem::temp_directory_path() / "matpredict_training_test_data";
    std::filesystem::remove_all(r);
    for (int k = 0; k < 4; ++k) write_sample(r, k);
    return r;
  }();
  return root;
}

// The quarter-width UNet-no-skip on the four images, one thread, output under the temp folder.
inline matlearn::TrainingConfig quick_config(const std::string& output) {
  matlearn::TrainingConfig c;
  c.dataset_root = four_image_dataset();
  c.train_samples = matdataset::index_dataset(c.dataset_root);
  c.network = "unet_no_skip";
  c.width_divisor = 4;
  c.image_size = kSize;
  c.batch_size = 4;
  c.threads = 1;
  c.learning_rate = 2e-3;
  c.output_dir = std::filesystem::temp_directory_path() / output;
  std::filesystem::remove_all(c.output_dir);
  return c;
}

}  // namespace training_dataset
