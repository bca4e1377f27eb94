#pragma once
// What every material regressor is to training and evaluation: an image-to-maps network whose
// only output-dependent part is its last 1x1 convolution (the paper's section on extensibility),
// chosen by name.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <torch/torch.h>

namespace matlearn {

class RegressorImpl : public torch::nn::Module {
 public:
  // N x 3 x H x W (normalised as the architecture's input_normalization says) to
  // N x output_channels x H x W, no activation. H and W must be multiples of side_multiple.
  virtual torch::Tensor forward(const torch::Tensor& image) = 0;
  // The ImageNet-pretrainable trunk whose torchvision weights scripts/convert_torchvision_weights.py
  // converts, or null for a network trained from scratch.
  virtual torch::nn::Module* encoder() { return nullptr; }
};

enum class Architecture {
  unet_no_skip,        // the paper's plain U-Net without long skips
  resnet50_u,          // the paper's ResNet-50 regressor
  swin_t_u,            // the paper's Swin-T regressor
  convnext_t_u,        // the paper's ConvNeXt-T regressor
  repo_resnet50_unet,  // the MatPredict repository's ResNet50UNet
  repo_swin_t_unet,    // the MatPredict repository's SwinTUNet
};

enum class InputNormalization { none, imagenet };

struct ArchitectureInfo {
  Architecture architecture;
  std::string name;                 // as the command line spells it
  std::string description;          // one line for --describe
  std::string torchvision_encoder;  // the model name convert_torchvision_weights.py takes, or ""
  InputNormalization input_normalization;
  int64_t side_multiple;  // input sides must be multiples of this
};

const std::vector<ArchitectureInfo>& architectures();
// Throws std::invalid_argument listing the known names.
const ArchitectureInfo& architecture_named(const std::string& name);
const ArchitectureInfo& info(Architecture architecture);

// The network with freshly initialised weights. width_divisor thins UNet-no-skip's channels (1 is
// the paper's network; 4 gives the quarter-width model of the quick default) and must be 1 for
// the others.
std::shared_ptr<RegressorImpl> make_regressor(Architecture architecture, int64_t output_channels,
                                              int64_t width_divisor = 1);
// Why make_regressor would refuse `width_divisor` for the architecture, or nothing.
std::optional<std::string> width_divisor_problem(Architecture architecture, int64_t width_divisor);

int64_t parameter_count(const torch::nn::Module& module);

}  // namespace matlearn
