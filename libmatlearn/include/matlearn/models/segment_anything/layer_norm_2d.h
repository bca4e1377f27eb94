#pragma once
// Segment Anything's LayerNorm2d: a LayerNorm over the channels of every pixel of an N x C x H x W
// tensor, with a scale and shift per channel (the necks and the mask path's convolutions).
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

class LayerNorm2dImpl : public torch::nn::Module {
 public:
  explicit LayerNorm2dImpl(int64_t channels, double eps = 1e-6);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  double eps_;
  torch::Tensor weight_, bias_;
};
TORCH_MODULE(LayerNorm2d);

}  // namespace matlearn
