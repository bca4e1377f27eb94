#pragma once
// The decoders' building blocks (docs/networks.md): "upconv", a 4x4 transposed
// convolution of stride 2 (doubling the resolution exactly) without bias + BatchNorm + ReLU, and
// "conv", a 3x3 convolution without bias + BatchNorm + ReLU.
#include <torch/torch.h>

namespace matlearn {

class UpConvImpl : public torch::nn::Module {
 public:
  UpConvImpl(int64_t in_channels, int64_t out_channels);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  torch::nn::ConvTranspose2d up_{nullptr};
  torch::nn::BatchNorm2d bn_{nullptr};
};
TORCH_MODULE(UpConv);

class ConvBnReluImpl : public torch::nn::Module {
 public:
  ConvBnReluImpl(int64_t in_channels, int64_t out_channels);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  torch::nn::Conv2d conv_{nullptr};
  torch::nn::BatchNorm2d bn_{nullptr};
};
TORCH_MODULE(ConvBnRelu);

}  // namespace matlearn
