#pragma once
// The MatPredict repository's decoder blocks (docs/networks.md, "The repository's two
// networks"), named as there ("block.0" ..., "up", "conv"): ConvBlock is two [3x3 convolution
// without bias, BatchNorm, ReLU]; UpBlock is a 2x2 stride-2 transposed convolution with bias, a
// bilinear resize to the skip's size where the sizes differ, concatenation with the skip and a
// ConvBlock.
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

class RepoConvBlockImpl : public torch::nn::Module {
 public:
  RepoConvBlockImpl(int64_t in_channels, int64_t out_channels);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  torch::nn::Sequential block_{nullptr};
};
TORCH_MODULE(RepoConvBlock);

class RepoUpBlockImpl : public torch::nn::Module {
 public:
  RepoUpBlockImpl(int64_t in_channels, int64_t skip_channels, int64_t out_channels);
  torch::Tensor forward(const torch::Tensor& x, const torch::Tensor& skip);

 private:
  torch::nn::ConvTranspose2d up_{nullptr};
  RepoConvBlock conv_{nullptr};
};
TORCH_MODULE(RepoUpBlock);

// The repository's plain 2x upsampling: ConvTranspose2d(k2, s2) with bias.
torch::nn::ConvTranspose2d repo_upsample(int64_t in_channels, int64_t out_channels);

}  // namespace matlearn
