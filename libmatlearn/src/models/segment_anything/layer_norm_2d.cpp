#include "matlearn/models/segment_anything/layer_norm_2d.h"

namespace matlearn {

LayerNorm2dImpl::LayerNorm2dImpl(int64_t channels, double eps) : eps_(eps) {
  weight_ = register_parameter("weight", torch::ones({channels}));
  bias_ = register_parameter("bias", torch::zeros({channels}));
}

torch::Tensor LayerNorm2dImpl::forward(const torch::Tensor& x) {
  const torch::Tensor mean = x.mean(1, /*keepdim=*/true);
  const torch::Tensor variance = (x - mean).pow(2).mean(1, /*keepdim=*/true);
  return weight_.view({1, -1, 1, 1}) * ((x - mean) / torch::sqrt(variance + eps_)) + bias_.view({1, -1, 1, 1});
}

}  // namespace matlearn
