#pragma once
// Swin-T-U and ConvNeXt-T-U, the paper's two modern regressors as docs/networks.md
// reconstructs them: the torchvision trunk's last stage (768 channels at 1/32) into the skip-free
// UpConvDecoder. Swin-T-U has 31,742,688 parameters for 6 outputs (paper 31.6M), ConvNeXt-T-U
// 32,041,926 (paper 32.0M). Input sides must be multiples of 32.
#include <cstdint>

#include "matlearn/models/convnext_encoder.h"
#include "matlearn/models/regressor.h"
#include "matlearn/models/swin_encoder.h"
#include "matlearn/models/upconv_decoder.h"

namespace matlearn {

class SwinTUImpl : public RegressorImpl {
 public:
  explicit SwinTUImpl(int64_t output_channels);
  torch::Tensor forward(const torch::Tensor& image) override;
  torch::nn::Module* encoder() override { return encoder_.get(); }

 private:
  SwinTEncoder encoder_{nullptr};
  UpConvDecoder decoder_{nullptr};
};
TORCH_MODULE(SwinTU);

class ConvNeXtTUImpl : public RegressorImpl {
 public:
  explicit ConvNeXtTUImpl(int64_t output_channels);
  torch::Tensor forward(const torch::Tensor& image) override;
  torch::nn::Module* encoder() override { return encoder_.get(); }

 private:
  ConvNeXtTEncoder encoder_{nullptr};
  UpConvDecoder decoder_{nullptr};
};
TORCH_MODULE(ConvNeXtTU);

}  // namespace matlearn
