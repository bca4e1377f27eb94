#pragma once
// The MatPredict repository's two later networks (docs/networks.md, "The repository's two
// networks"), offered beside the paper's four:
// - RepoResNet50UNet: the torchvision ResNet-50 trunk, a ConvBlock 2048 -> 1024 bottleneck, four
//   UpBlocks with the layer3, layer2, layer1 and stem skips (512, 256, 128, 64 channels), a 2x
//   upsampling to 32 channels, a ConvBlock and the 1x1 head: 67,137,605 parameters for the
//   repository's 5 outputs, as it counts.
// - RepoSwinTUNet: the Swin-T trunk (ours is torchvision's, where the repository uses timm's
//   equivalent), a ConvBlock 768 -> 768 bottleneck, UpBlocks with the 1/16, 1/8 and 1/4 skips,
//   then two skip-free 2x upsamplings with ConvBlocks (64, 32) and the head. The repository counts
//   45,040,448 for 6 outputs with timm's trunk; ours adds the trunk's final LayerNorm (1,536),
//   applied to the last stage as torchvision does.
// Input sides must be multiples of 32.
#include <cstdint>

#include "matlearn/models/regressor.h"
#include "matlearn/models/repo_unet_blocks.h"
#include "matlearn/models/resnet_encoder.h"
#include "matlearn/models/swin_encoder.h"

namespace matlearn {

class RepoResNet50UNetImpl : public RegressorImpl {
 public:
  explicit RepoResNet50UNetImpl(int64_t output_channels);
  torch::Tensor forward(const torch::Tensor& image) override;
  torch::nn::Module* encoder() override { return encoder_.get(); }

 private:
  ResNet50Encoder encoder_{nullptr};
  RepoConvBlock bottleneck_{nullptr}, final_conv_{nullptr};
  RepoUpBlock up4_{nullptr}, up3_{nullptr}, up2_{nullptr}, up1_{nullptr};
  torch::nn::ConvTranspose2d final_up_{nullptr};
  torch::nn::Conv2d head_{nullptr};
};
TORCH_MODULE(RepoResNet50UNet);

class RepoSwinTUNetImpl : public RegressorImpl {
 public:
  explicit RepoSwinTUNetImpl(int64_t output_channels);
  torch::Tensor forward(const torch::Tensor& image) override;
  torch::nn::Module* encoder() override { return encoder_.get(); }

 private:
  SwinTEncoder encoder_{nullptr};
  RepoConvBlock bottleneck_{nullptr}, conv1_{nullptr}, final_conv_{nullptr};
  RepoUpBlock up4_{nullptr}, up3_{nullptr}, up2_{nullptr};
  torch::nn::ConvTranspose2d up1_{nullptr}, final_up_{nullptr};
  torch::nn::Conv2d head_{nullptr};
};
TORCH_MODULE(RepoSwinTUNet);

}  // namespace matlearn
