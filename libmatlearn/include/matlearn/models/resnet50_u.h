#pragma once
// ResNet50-U, the paper's ResNet-50 regressor as docs/networks.md reconstructs it
// (39,642,470 parameters for 6 outputs, the paper's 39.5M within 0.4 %): the torchvision ResNet-50
// trunk; a conv 2048 -> 512 at 1/32; five stages of [upconv, concatenation with the encoder's
// skip (layer3, layer2, layer1, stem, none), conv] down to 256, 128, 64, 32, 16 channels at full
// resolution; a 1x1 convolution to the output maps. Only that last convolution depends on the
// number of output channels. Input sides must be multiples of 32.
#include <torch/torch.h>

#include "matlearn/models/decoder_blocks.h"
#include "matlearn/models/regressor.h"
#include "matlearn/models/resnet_encoder.h"

namespace matlearn {

class ResNet50UImpl : public RegressorImpl {
 public:
  explicit ResNet50UImpl(int64_t output_channels);
  torch::Tensor forward(const torch::Tensor& image) override;
  torch::nn::Module* encoder() override { return encoder_.get(); }

 private:
  ResNet50Encoder encoder_{nullptr};
  ConvBnRelu bottleneck_{nullptr};
  torch::nn::ModuleList up_{nullptr}, fuse_{nullptr};
  torch::nn::Conv2d head_{nullptr};
};
TORCH_MODULE(ResNet50U);

}  // namespace matlearn
