#include "matlearn/models/repo_unet_blocks.h"

#include "matlearn/models/transposed_convolution.h"

namespace matlearn {

namespace nn = torch::nn;

RepoConvBlockImpl::RepoConvBlockImpl(int64_t in_channels, int64_t out_channels) {
  block_ = register_module(
      "block", nn::Sequential(nn::Conv2d(nn::Conv2dOptions(in_channels, out_channels, 3).padding(1).bias(false)),
                              nn::BatchNorm2d(out_channels), nn::ReLU(),
                              nn::Conv2d(nn::Conv2dOptions(out_channels, out_channels, 3).padding(1).bias(false)),
                              nn::BatchNorm2d(out_channels), nn::ReLU()));
}

torch::Tensor RepoConvBlockImpl::forward(const torch::Tensor& x) { return block_->forward(x); }

nn::ConvTranspose2d repo_upsample(int64_t in_channels, int64_t out_channels) {
  return nn::ConvTranspose2d(nn::ConvTranspose2dOptions(in_channels, out_channels, 2).stride(2));
}

RepoUpBlockImpl::RepoUpBlockImpl(int64_t in_channels, int64_t skip_channels, int64_t out_channels) {
  up_ = register_module("up", repo_upsample(in_channels, out_channels));
  conv_ = register_module("conv", RepoConvBlock(out_channels + skip_channels, out_channels));
}

torch::Tensor RepoUpBlockImpl::forward(const torch::Tensor& x, const torch::Tensor& skip) {
  torch::Tensor up = transposed_convolution(*up_, x);
  if (up.sizes().slice(2) != skip.sizes().slice(2))
    up = nn::functional::interpolate(up, nn::functional::InterpolateFuncOptions()
                                             .size(std::vector<int64_t>{skip.size(2), skip.size(3)})
                                             .mode(torch::kBilinear)
                                             .align_corners(false));
  return conv_->forward(torch::cat({up, skip}, 1));
}

}  // namespace matlearn
