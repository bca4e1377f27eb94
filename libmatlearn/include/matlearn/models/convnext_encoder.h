#pragma once
// The ConvNeXt-T trunk (Liu et al. 2022, "A ConvNet for the 2020s"), laid out exactly as
// torchvision 0.14's convnext_tiny without its classifier: "features.0" (4x4 patchify convolution
// + LayerNorm), "features.1, 3, 5, 7" (stages of 3, 3, 9, 3 blocks at 96, 192, 384, 768 channels)
// and "features.2, 4, 6" (LayerNorm + 2x2 stride-2 convolution), so torchvision's parameter names
// and shapes are ours and its state dict loads unchanged (27,818,592 parameters).
#include <array>
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

// LayerNorm over the channels of an NCHW tensor (torchvision's LayerNorm2d), eps 1e-6.
class ChannelLayerNormImpl : public torch::nn::Module {
 public:
  explicit ChannelLayerNormImpl(int64_t channels);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  torch::Tensor weight_, bias_;
};
TORCH_MODULE(ChannelLayerNorm);

// x + layer_scale * (7x7 depthwise conv, LayerNorm, linear to 4C, GELU, linear to C), the branch
// under stochastic depth; the linears work on NHWC as torchvision's.
class ConvNeXtBlockImpl : public torch::nn::Module {
 public:
  ConvNeXtBlockImpl(int64_t channels, double drop_probability);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  double drop_probability_;
  torch::nn::Sequential block_{nullptr};
  torch::Tensor layer_scale_;
};
TORCH_MODULE(ConvNeXtBlock);

// The four stages' outputs, NCHW; for a 224 input 96@56, 192@28, 384@14, 768@7.
struct ConvNeXtFeatures {
  std::array<torch::Tensor, 4> stages;
};

class ConvNeXtTEncoderImpl : public torch::nn::Module {
 public:
  ConvNeXtTEncoderImpl();
  ConvNeXtFeatures forward(const torch::Tensor& image);

 private:
  torch::nn::ModuleList features_{nullptr};
};
TORCH_MODULE(ConvNeXtTEncoder);

}  // namespace matlearn
