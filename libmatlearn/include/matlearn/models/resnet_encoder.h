#pragma once
// The ResNet-50 trunk (He et al. 2016, "Deep Residual Learning for Image Recognition"), laid out
// exactly as torchvision 0.14's resnet50 without its classifier: the same module tree, so the
// parameter and buffer names and shapes match ("conv1.weight", "layer1.0.downsample.1.running_mean",
// ...) and a torchvision state dict loads unchanged (scripts/convert_torchvision_weights.py).
// Bottlenecks stride in their 3x3 convolution (torchvision's "ResNet v1.5").
#include <torch/torch.h>

namespace matlearn {

// Torchvision's Bottleneck: 1x1 reduce, 3x3 (stride), 1x1 expand by 4, each with BatchNorm; the
// shortcut is a strided 1x1 convolution + BatchNorm where the shape changes.
class BottleneckImpl : public torch::nn::Module {
 public:
  BottleneckImpl(int64_t in_channels, int64_t width, int64_t stride);
  torch::Tensor forward(const torch::Tensor& x);

 private:
  torch::nn::Conv2d conv1_{nullptr}, conv2_{nullptr}, conv3_{nullptr};
  torch::nn::BatchNorm2d bn1_{nullptr}, bn2_{nullptr}, bn3_{nullptr};
  torch::nn::Sequential downsample_{nullptr};
};
TORCH_MODULE(Bottleneck);

// Feature maps at each stage, NCHW; for a 224 input: stem 64@112, layer1 256@56, layer2 512@28,
// layer3 1024@14, layer4 2048@7.
struct ResNetFeatures {
  torch::Tensor stem, layer1, layer2, layer3, layer4;
};

class ResNet50EncoderImpl : public torch::nn::Module {
 public:
  ResNet50EncoderImpl();
  ResNetFeatures forward(const torch::Tensor& image);

 private:
  torch::nn::Conv2d conv1_{nullptr};
  torch::nn::BatchNorm2d bn1_{nullptr};
  torch::nn::Sequential layer1_{nullptr}, layer2_{nullptr}, layer3_{nullptr}, layer4_{nullptr};
};
TORCH_MODULE(ResNet50Encoder);

}  // namespace matlearn
