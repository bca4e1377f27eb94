#pragma once
// The dataset train_regressor trains on when it is given none: built-in objects in a few
// constant materials of different families, rendered with libmatrender under the paper's light
// rig from several grid cameras, written in the MatPredict repository's layout
// (<root>/<object>/var<NNN>/{images,albedo,ORM,normal_obj,label}/<NNN>.png), with pixel-aligned
// maps.
#include <filesystem>
#include <functional>

namespace train_regressor {

struct ExampleDatasetSize {
  int views = 8;          // per object and material
  int resolution = 64;    // pixels per side
  int samples = 16;       // per pixel
};

// Renders the dataset into `root` unless a complete one of this version is there already (a
// marker file written last says so); returns the number of samples. progress(done, total) follows each image.
int render_example_dataset(const std::filesystem::path& root, const ExampleDatasetSize& size,
                           const std::function<void(int, int)>& progress = {});

}  // namespace train_regressor
