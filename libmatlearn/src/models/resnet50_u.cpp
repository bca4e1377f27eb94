#include "matlearn/models/resnet50_u.h"

#include <array>

namespace matlearn {

namespace {

// Decoder widths, and the channels of the skip each stage concatenates (0: none).
constexpr std::array<int64_t, 5> kWidths = {256, 128, 64, 32, 16};
constexpr std::array<int64_t, 5> kSkipChannels = {1024, 512, 256, 64, 0};

}  // namespace

ResNet50UImpl::ResNet50UImpl(int64_t output_channels) {
  encoder_ = register_module("encoder", ResNet50Encoder());
  bottleneck_ = register_module("bottleneck", ConvBnRelu(2048, 512));
  up_ = register_module("up", torch::nn::ModuleList());
  fuse_ = register_module("fuse", torch::nn::ModuleList());
  int64_t channels = 512;
  for (size_t s = 0; s < kWidths.size(); ++s) {
    up_->push_back(UpConv(channels, kWidths[s]));
    fuse_->push_back(ConvBnRelu(kWidths[s] + kSkipChannels[s], kWidths[s]));
    channels = kWidths[s];
  }
  head_ = register_module("head", torch::nn::Conv2d(torch::nn::Conv2dOptions(channels, output_channels, 1)));
}

torch::Tensor ResNet50UImpl::forward(const torch::Tensor& image) {
  const ResNetFeatures f = encoder_->forward(image);
  const std::array<torch::Tensor, 4> skips = {f.layer3, f.layer2, f.layer1, f.stem};
  torch::Tensor x = bottleneck_->forward(f.layer4);
  for (size_t s = 0; s < kWidths.size(); ++s) {
    x = up_[s]->as<UpConv>()->forward(x);
    if (s < skips.size()) x = torch::cat({x, skips[s]}, 1);
    x = fuse_[s]->as<ConvBnRelu>()->forward(x);
  }
  return head_->forward(x);
}

}  // namespace matlearn
