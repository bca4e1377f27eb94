#include "matlearn/models/repo_unets.h"

#include "matlearn/models/transposed_convolution.h"

namespace matlearn {

namespace nn = torch::nn;

RepoResNet50UNetImpl::RepoResNet50UNetImpl(int64_t output_channels) {
  encoder_ = register_module("encoder", ResNet50Encoder());
  bottleneck_ = register_module("bottleneck", RepoConvBlock(2048, 1024));
  up4_ = register_module("up4", RepoUpBlock(1024, 1024, 512));
  up3_ = register_module("up3", RepoUpBlock(512, 512, 256));
  up2_ = register_module("up2", RepoUpBlock(256, 256, 128));
  up1_ = register_module("up1", RepoUpBlock(128, 64, 64));
  final_up_ = register_module("final_up", repo_upsample(64, 32));
  final_conv_ = register_module("final_conv", RepoConvBlock(32, 32));
  head_ = register_module("head", nn::Conv2d(nn::Conv2dOptions(32, output_channels, 1)));
}

torch::Tensor RepoResNet50UNetImpl::forward(const torch::Tensor& image) {
  const ResNetFeatures f = encoder_->forward(image);
  torch::Tensor x = bottleneck_->forward(f.layer4);
  x = up1_->forward(up2_->forward(up3_->forward(up4_->forward(x, f.layer3), f.layer2), f.layer1), f.stem);
  return head_->forward(final_conv_->forward(transposed_convolution(*final_up_, x)));
}

RepoSwinTUNetImpl::RepoSwinTUNetImpl(int64_t output_channels) {
  encoder_ = register_module("encoder", SwinTEncoder());
  bottleneck_ = register_module("bottleneck", RepoConvBlock(768, 768));
  up4_ = register_module("up4", RepoUpBlock(768, 384, 384));
  up3_ = register_module("up3", RepoUpBlock(384, 192, 192));
  up2_ = register_module("up2", RepoUpBlock(192, 96, 96));
  up1_ = register_module("up1", repo_upsample(96, 64));
  conv1_ = register_module("conv1", RepoConvBlock(64, 64));
  final_up_ = register_module("final_up", repo_upsample(64, 32));
  final_conv_ = register_module("final_conv", RepoConvBlock(32, 32));
  head_ = register_module("head", nn::Conv2d(nn::Conv2dOptions(32, output_channels, 1)));
}

torch::Tensor RepoSwinTUNetImpl::forward(const torch::Tensor& image) {
  const SwinFeatures f = encoder_->forward(image);
  torch::Tensor x = bottleneck_->forward(f.stages[3]);
  x = up2_->forward(up3_->forward(up4_->forward(x, f.stages[2]), f.stages[1]), f.stages[0]);
  x = conv1_->forward(transposed_convolution(*up1_, x));
  return head_->forward(final_conv_->forward(transposed_convolution(*final_up_, x)));
}

}  // namespace matlearn
