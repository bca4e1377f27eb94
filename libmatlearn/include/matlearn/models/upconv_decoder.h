#pragma once
// The skip-free decoder of Swin-T-U and ConvNeXt-T-U (docs/networks.md): a 1x1
// convolution (no bias) + BatchNorm + ReLU from the encoder's 768 channels at 1/32 to 384, five
// upconvs to 384, 192, 96, 48 and 24 channels at full resolution, and the 1x1 output convolution
// (4,223,334 parameters for 6 outputs).
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

class UpConvDecoderImpl : public torch::nn::Module {
 public:
  UpConvDecoderImpl(int64_t input_channels, int64_t output_channels);
  torch::Tensor forward(const torch::Tensor& features);  // N x input_channels x H/32 x W/32

 private:
  torch::nn::Sequential reduce_{nullptr}, up_{nullptr};
  torch::nn::Conv2d head_{nullptr};
};
TORCH_MODULE(UpConvDecoder);

}  // namespace matlearn
