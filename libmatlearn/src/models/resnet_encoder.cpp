#include "matlearn/models/resnet_encoder.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

nn::Conv2d convolution(int64_t in, int64_t out, int64_t kernel, int64_t stride) {
  return nn::Conv2d(nn::Conv2dOptions(in, out, kernel).stride(stride).padding(kernel / 2).bias(false));
}

// A stage of `blocks` bottlenecks, the first of which may stride and widen (torchvision's
// _make_layer); returns the stage and its output channels.
nn::Sequential make_stage(int64_t& in_channels, int64_t width, int64_t blocks, int64_t stride) {
  nn::Sequential stage;
  for (int64_t b = 0; b < blocks; ++b) {
    stage->push_back(Bottleneck(in_channels, width, b == 0 ? stride : 1));
    in_channels = width * 4;
  }
  return stage;
}

}  // namespace

BottleneckImpl::BottleneckImpl(int64_t in_channels, int64_t width, int64_t stride) {
  const int64_t out_channels = width * 4;
  conv1_ = register_module("conv1", convolution(in_channels, width, 1, 1));
  bn1_ = register_module("bn1", nn::BatchNorm2d(width));
  conv2_ = register_module("conv2", convolution(width, width, 3, stride));
  bn2_ = register_module("bn2", nn::BatchNorm2d(width));
  conv3_ = register_module("conv3", convolution(width, out_channels, 1, 1));
  bn3_ = register_module("bn3", nn::BatchNorm2d(out_channels));
  if (stride != 1 || in_channels != out_channels)
    downsample_ = register_module(
        "downsample", nn::Sequential(convolution(in_channels, out_channels, 1, stride), nn::BatchNorm2d(out_channels)));
}

// In-place ReLUs and sum, as torchvision's: fewer temporaries (autograd allows it, since neither
// BatchNorm's nor the sum's backward needs the tensors overwritten).
torch::Tensor BottleneckImpl::forward(const torch::Tensor& x) {
  torch::Tensor y = bn1_->forward(conv1_->forward(x)).relu_();
  y = bn2_->forward(conv2_->forward(y)).relu_();
  y = bn3_->forward(conv3_->forward(y));
  y += downsample_ ? downsample_->forward(x) : x;
  return y.relu_();
}

ResNet50EncoderImpl::ResNet50EncoderImpl() {
  conv1_ = register_module("conv1", nn::Conv2d(nn::Conv2dOptions(3, 64, 7).stride(2).padding(3).bias(false)));
  bn1_ = register_module("bn1", nn::BatchNorm2d(64));
  int64_t channels = 64;
  layer1_ = register_module("layer1", make_stage(channels, 64, 3, 1));
  layer2_ = register_module("layer2", make_stage(channels, 128, 4, 2));
  layer3_ = register_module("layer3", make_stage(channels, 256, 6, 2));
  layer4_ = register_module("layer4", make_stage(channels, 512, 3, 2));
  // torchvision's initialisation: He (fan_out) normal for convolutions; BatchNorm keeps weight 1,
  // bias 0.
  torch::NoGradGuard no_grad;
  for (auto& p : parameters())
    if (p.dim() == 4) nn::init::kaiming_normal_(p, 0.0, torch::kFanOut, torch::kReLU);
}

ResNetFeatures ResNet50EncoderImpl::forward(const torch::Tensor& image) {
  ResNetFeatures f;
  f.stem = bn1_->forward(conv1_->forward(image)).relu_();
  f.layer1 = layer1_->forward(torch::max_pool2d(f.stem, 3, 2, 1));
  f.layer2 = layer2_->forward(f.layer1);
  f.layer3 = layer3_->forward(f.layer2);
  f.layer4 = layer4_->forward(f.layer3);
  return f;
}

}  // namespace matlearn
