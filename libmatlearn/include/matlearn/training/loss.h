#pragma once
// The training objective on a network's raw output. Every regression channel goes through a
// sigmoid, here and wherever maps are read out (predicted_maps), so evaluation scores what was
// trained (the repository's W1: it trained on sigmoid but scored clamp(logits, 0, 1)).
#include <vector>

#include <torch/torch.h>

#include "matlearn/training/batch.h"
#include "matlearn/training/output_layout.h"

namespace matlearn {

// The paper's squared error, or the repository's absolute error.
enum class RegressionLoss { mse, l1 };

struct LossTerms {
  torch::Tensor total;              // scalar, differentiable
  std::vector<double> group_terms;  // each map's unweighted term, in the layout's order
  double material_term = 0.0;       // unweighted cross-entropy, 0 without a segmentation head
};

// Each map's term is its error over the object's pixels and channels, pooled over the batch
// (sum of errors * mask / (channels * sum of mask)); the material term is the cross-entropy over
// every labelled pixel, background included as class 0. total = sum of weight * term.
LossTerms training_loss(const torch::Tensor& output, const Batch& batch, const OutputLayout& layout,
                        RegressionLoss loss);

// The maps in [0, 1] (N x regression_channels x H x W): sigmoid of the regression channels.
torch::Tensor predicted_maps(const torch::Tensor& output, const OutputLayout& layout);

}  // namespace matlearn
