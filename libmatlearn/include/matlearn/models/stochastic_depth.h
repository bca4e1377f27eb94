#pragma once
// Stochastic depth (Huang et al. 2016, "Deep Networks with Stochastic Depth"), "row" mode as
// torchvision's stochastic_depth: in training, each sample's residual branch is dropped with
// probability p and kept ones are scaled by 1 / (1 - p); in evaluation the branch passes
// unchanged. Draws from torch's default generator.
#include <torch/torch.h>

namespace matlearn {

torch::Tensor drop_residual_rows(const torch::Tensor& branch, double drop_probability, bool training);

// Block b of `blocks` drops with probability max_probability * b / (blocks - 1), the linear
// rule of torchvision's Swin and ConvNeXt.
double block_drop_probability(double max_probability, int64_t block, int64_t blocks);

}  // namespace matlearn
