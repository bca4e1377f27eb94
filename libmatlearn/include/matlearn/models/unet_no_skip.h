#pragma once
// UNet-no-skip, the paper's plain baseline as docs/networks.md reconstructs it
// (23,730,758 parameters for 6 outputs, the paper's 23.6M within 0.6 %): a U-Net encoder of
// double 3x3 convolutions with 64, 128, 256, 512 channels and four 2x2 max-pools to a 1024-channel
// bottleneck at 1/16, then four upconvs 1024 -> 256 -> 128 -> 64 -> 32 without the U-Net's long
// skips, and a 1x1 convolution to the output maps. Input sides must be multiples of 16.
// width_divisor > 1 divides every width (4: the quarter-width network of the quick default,
// about 1.5M parameters).
#include <torch/torch.h>

#include "matlearn/models/decoder_blocks.h"
#include "matlearn/models/regressor.h"

namespace matlearn {

class UNetNoSkipImpl : public RegressorImpl {
 public:
  explicit UNetNoSkipImpl(int64_t output_channels, int64_t width_divisor = 1);
  torch::Tensor forward(const torch::Tensor& image) override;

 private:
  torch::nn::ModuleList encoder_{nullptr}, decoder_{nullptr};
  torch::nn::Conv2d head_{nullptr};
};
TORCH_MODULE(UNetNoSkip);

}  // namespace matlearn
