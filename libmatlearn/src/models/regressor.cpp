#include "matlearn/models/regressor.h"

#include <stdexcept>

#include "matlearn/models/repo_unets.h"
#include "matlearn/models/resnet50_u.h"
#include "matlearn/models/swin_convnext_u.h"
#include "matlearn/models/unet_no_skip.h"

namespace matlearn {

// Networks with an ImageNet-pretrainable trunk take ImageNet-normalised input, the statistics
// their trunk's weights were trained with (the paper normalised Swin-T only, the repository
// every network); UNet-no-skip learns from scratch on [0, 1].
const std::vector<ArchitectureInfo>& architectures() {
  static const std::vector<ArchitectureInfo> list = {
      {Architecture::unet_no_skip, "unet_no_skip", "U-Net encoder 64..1024 without long skips, 4 upconvs",
       "", InputNormalization::none, 16},
      {Architecture::resnet50_u, "resnet50_u", "ResNet-50 trunk, U-Net-style decoder with skips",
       "resnet50", InputNormalization::imagenet, 32},
      {Architecture::swin_t_u, "swin_t_u", "Swin-T trunk, 1x1 + 5 upconvs, no skips", "swin_t",
       InputNormalization::imagenet, 32},
      {Architecture::convnext_t_u, "convnext_t_u", "ConvNeXt-T trunk, 1x1 + 5 upconvs, no skips",
       "convnext_tiny", InputNormalization::imagenet, 32},
      {Architecture::repo_resnet50_unet, "repo_resnet50_unet",
       "the MatPredict repository's ResNet50UNet (67.1M with 5 outputs)", "resnet50", InputNormalization::imagenet,
       32},
      {Architecture::repo_swin_t_unet, "repo_swin_t_unet", "the MatPredict repository's SwinTUNet (45.0M)", "swin_t",
       InputNormalization::imagenet, 32},
  };
  return list;
}

const ArchitectureInfo& architecture_named(const std::string& name) {
  std::string known;
  for (const ArchitectureInfo& a : architectures()) {
    if (a.name == name) return a;
    known += (known.empty() ? "" : ", ") + a.name;
  }
  throw std::invalid_argument("unknown network \"" + name + "\" (known: " + known + ")");
}

const ArchitectureInfo& info(Architecture architecture) {
  for (const ArchitectureInfo& a : architectures())
    if (a.architecture == architecture) return a;
  throw std::logic_error("architecture missing from the table");
}

std::optional<std::string> width_divisor_problem(Architecture architecture, int64_t width_divisor) {
  if (width_divisor != 1 && architecture != Architecture::unet_no_skip)
    return "only unet_no_skip can be thinned (width divisor " + std::to_string(width_divisor) + ")";
  // Every width divides exactly, down to the last decoder stage's 32 channels, which keeps at least 1.
  if (width_divisor < 1 || 32 % width_divisor != 0)
    return "the width divisor must be 1, 2, 4, 8, 16 or 32 (a divisor of 32), got " + std::to_string(width_divisor);
  return std::nullopt;
}

std::shared_ptr<RegressorImpl> make_regressor(Architecture architecture, int64_t output_channels,
                                              int64_t width_divisor) {
  if (const std::optional<std::string> problem = width_divisor_problem(architecture, width_divisor))
    throw std::invalid_argument(*problem);
  switch (architecture) {
    case Architecture::unet_no_skip: return std::make_shared<UNetNoSkipImpl>(output_channels, width_divisor);
    case Architecture::resnet50_u: return std::make_shared<ResNet50UImpl>(output_channels);
    case Architecture::swin_t_u: return std::make_shared<SwinTUImpl>(output_channels);
    case Architecture::convnext_t_u: return std::make_shared<ConvNeXtTUImpl>(output_channels);
    case Architecture::repo_resnet50_unet: return std::make_shared<RepoResNet50UNetImpl>(output_channels);
    case Architecture::repo_swin_t_unet: return std::make_shared<RepoSwinTUNetImpl>(output_channels);
  }
  throw std::logic_error("unhandled architecture");
}

int64_t parameter_count(const torch::nn::Module& module) {
  int64_t count = 0;
  for (const torch::Tensor& p : module.parameters()) count += p.numel();
  return count;
}

}  // namespace matlearn
