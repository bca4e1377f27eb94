#pragma once
// Small training pairs for the learned denoiser, rendered on the spot: a vase and a chair in
// raw wood and polished metal, two views each, with the colour in floats (render.hdr_images),
// once at many samples (reference/) and once at few (noisy/, another render.seed). What
// train_denoiser trains on when given nothing, and what its tests train on.
#include <cstddef>
#include <filesystem>
#include <functional>

namespace matdataset {

struct ExamplePairs {
  std::filesystem::path reference;
  std::filesystem::path noisy;
};

// Renders them into `root` (resuming what is there) at `side` pixels; `progress(done, total)`
// after every frame of each of the two datasets.
ExamplePairs render_example_pairs(const std::filesystem::path& root, int side, int reference_samples, int noisy_samples,
                                  const std::function<void(const char* dataset, size_t done, size_t total)>& progress = {});

}  // namespace matdataset
