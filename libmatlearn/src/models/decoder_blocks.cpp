#include "matlearn/models/decoder_blocks.h"

#include "matlearn/models/transposed_convolution.h"

namespace matlearn {

namespace nn = torch::nn;

UpConvImpl::UpConvImpl(int64_t in_channels, int64_t out_channels) {
  up_ = register_module(
      "up", nn::ConvTranspose2d(nn::ConvTranspose2dOptions(in_channels, out_channels, 4).stride(2).padding(1).bias(false)));
  bn_ = register_module("bn", nn::BatchNorm2d(out_channels));
}

// In-place ReLU: BatchNorm's backward does not need its output.
torch::Tensor UpConvImpl::forward(const torch::Tensor& x) {
  return bn_->forward(transposed_convolution(*up_, x)).relu_();
}

ConvBnReluImpl::ConvBnReluImpl(int64_t in_channels, int64_t out_channels) {
  conv_ = register_module("conv", nn::Conv2d(nn::Conv2dOptions(in_channels, out_channels, 3).padding(1).bias(false)));
  bn_ = register_module("bn", nn::BatchNorm2d(out_channels));
}

torch::Tensor ConvBnReluImpl::forward(const torch::Tensor& x) { return bn_->forward(conv_->forward(x)).relu_(); }

}  // namespace matlearn
