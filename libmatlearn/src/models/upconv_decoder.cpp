#include "matlearn/models/upconv_decoder.h"

#include <array>

#include "matlearn/models/decoder_blocks.h"

namespace matlearn {

namespace nn = torch::nn;

UpConvDecoderImpl::UpConvDecoderImpl(int64_t input_channels, int64_t output_channels) {
  constexpr std::array<int64_t, 5> kWidths = {384, 192, 96, 48, 24};
  reduce_ = register_module("reduce", nn::Sequential(nn::Conv2d(nn::Conv2dOptions(input_channels, kWidths[0], 1).bias(false)),
                                                     nn::BatchNorm2d(kWidths[0]), nn::ReLU()));
  up_ = register_module("up", nn::Sequential());
  int64_t channels = kWidths[0];
  for (int64_t width : kWidths) {
    up_->push_back(UpConv(channels, width));
    channels = width;
  }
  head_ = register_module("head", nn::Conv2d(nn::Conv2dOptions(channels, output_channels, 1)));
}

torch::Tensor UpConvDecoderImpl::forward(const torch::Tensor& features) {
  return head_->forward(up_->forward(reduce_->forward(features)));
}

}  // namespace matlearn
