#pragma once
// Decoded samples (matdataset/format/sample_reader.h) stacked into the tensors a training step uses.
#include <vector>

#include <torch/torch.h>

#include "matdataset/format/sample_reader.h"
#include "matlearn/models/regressor.h"
#include "matlearn/training/output_layout.h"

namespace matlearn {

struct Batch {
  torch::Tensor input;   // N x 3 x H x W, normalised for the network
  torch::Tensor target;  // N x regression_channels x H x W in [0, 1], in the layout's order
  torch::Tensor mask;    // N x 1 x H x W, 1 on the object
  torch::Tensor labels;  // N x H x W material ids (int64); kIgnoredLabel where a sample has no label
};

// The label of pixels that carry none (cross-entropy skips them), torch's default ignore index.
constexpr int64_t kIgnoredLabel = -100;

// How to read samples for a network of this layout: maps at image_size, the albedo linear or
// as stored, the normal and metallic maps when the layout predicts them, and the label when it
// has a segmentation head, its ids below the head's classes.
matdataset::SampleSettings sample_settings(const OutputLayout& layout, int image_size, bool linear_albedo);

// The sample's map for the group, a grey map repeated to the group's channel count.
matbase::FloatImage target_map(const matdataset::MaterialSample& sample, const OutputGroup& group);

Batch make_batch(const std::vector<matdataset::MaterialSample>& samples, const OutputLayout& layout,
                 InputNormalization normalization);

// RGB in [0, 1], N x 3 x H x W, normalised with ImageNet's mean and standard deviation or not.
torch::Tensor normalize_input(const torch::Tensor& rgb, InputNormalization normalization);

// An HWC image as a C x H x W tensor (a copy), and back.
torch::Tensor to_chw(const matbase::FloatImage& image);
matbase::FloatImage to_hwc(const torch::Tensor& chw);

}  // namespace matlearn
