#pragma once
// The dataset train_regressor trains on when it is given none: made by make_dataset's own code
// (apps/make_dataset) from a small configuration: the built-in vase and chair in four library
// materials of different classes, under the paper's light rig, from a ring of grid cameras 30
// degrees above the horizon, in the MatPredict repository's layout with pixel-aligned maps.
#include <filesystem>
#include <functional>

namespace train_regressor {

struct ExampleDatasetSize {
  int views = 8;          // per object and material
  int resolution = 64;    // pixels per side
  int samples = 16;       // per pixel
};

// Renders into `root` whatever frames of the dataset are not there whole already (so a second
// call renders nothing) and returns the number of samples. progress(done, total) follows each frame.
int render_example_dataset(const std::filesystem::path& root, const ExampleDatasetSize& size,
                           const std::function<void(int, int)>& progress = {});

}  // namespace train_regressor
