#include "matlearn/models/unet_no_skip.h"

#include <array>

namespace matlearn {
namespace {

constexpr std::array<int64_t, 5> kEncoderWidths = {64, 128, 256, 512, 1024};  // the last is the bottleneck
constexpr std::array<int64_t, 4> kDecoderWidths = {256, 128, 64, 32};

// U-Net's DoubleConv: two conv blocks.
torch::nn::Sequential double_conv(int64_t in_channels, int64_t out_channels) {
  return torch::nn::Sequential(ConvBnRelu(in_channels, out_channels), ConvBnRelu(out_channels, out_channels));
}

}  // namespace

UNetNoSkipImpl::UNetNoSkipImpl(int64_t output_channels, int64_t width_divisor) {
  encoder_ = register_module("encoder", torch::nn::ModuleList());
  decoder_ = register_module("decoder", torch::nn::ModuleList());
  int64_t channels = 3;
  for (int64_t width : kEncoderWidths) {
    encoder_->push_back(double_conv(channels, width / width_divisor));
    channels = width / width_divisor;
  }
  for (int64_t width : kDecoderWidths) {
    decoder_->push_back(UpConv(channels, width / width_divisor));
    channels = width / width_divisor;
  }
  head_ = register_module("head", torch::nn::Conv2d(torch::nn::Conv2dOptions(channels, output_channels, 1)));
}

torch::Tensor UNetNoSkipImpl::forward(const torch::Tensor& image) {
  torch::Tensor x = image;
  for (size_t i = 0; i < encoder_->size(); ++i) {
    if (i > 0) x = torch::max_pool2d(x, 2);
    x = encoder_[i]->as<torch::nn::Sequential>()->forward(x);
  }
  for (const auto& up : *decoder_) x = up->as<UpConv>()->forward(x);
  return head_->forward(x);
}

}  // namespace matlearn
