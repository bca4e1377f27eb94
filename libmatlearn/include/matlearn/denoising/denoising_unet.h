#pragma once
// The learned denoiser's network: the U-Net of Open Image Denoise (Afra et al., "Intel Open Image
// Denoise", 2019-; the design in Chaitanya et al. 2017, "Interactive Reconstruction of Monte
// Carlo Image Sequences using a Recurrent Denoising Autoencoder", without the recurrence), with
// OIDN's sizes:
//   full size   3x3 convolutions 9 -> 32 -> 32, 2x2 max-pool
//   1/2         32 -> 48, pool
//   1/4         48 -> 64, pool
//   1/8         64 -> 80, pool
//   1/16        80 -> 96 -> 96 (the bottleneck)
//   up to 1/8,  concatenate the 1/8 features (64):  160 -> 112 -> 112
//   up to 1/4,  concatenate the 1/4 features (48):  160 -> 96 -> 96
//   up to 1/2,  concatenate the 1/2 features (32):  128 -> 64 -> 64
//   up to 1/1,  concatenate the input itself (9):    73 -> 64 -> 32, then 32 -> 3 (no activation)
// Every convolution but the last is followed by a ReLU; upsampling is nearest-neighbour. 920,000
// parameters or so (3.7 MB in float32). Input sides must be multiples of 16 (four poolings).
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

// The input's channels: the colour through the HDR transfer function (3), the albedo (3), the
// normal (3) (denoiser_input.h).
constexpr int64_t kDenoiserInputChannels = 9;
// Four poolings: every input side is padded to a multiple of this.
constexpr int64_t kDenoiserSideMultiple = 16;

class DenoisingUNetImpl : public torch::nn::Module {
 public:
  DenoisingUNetImpl();
  // input: N x 9 x H x W, H and W multiples of 16; returns N x 3 x H x W, the colour in the
  // transfer function's range (not clamped).
  torch::Tensor forward(const torch::Tensor& input);

 private:
  torch::nn::Conv2d enc_conv0_{nullptr}, enc_conv1_{nullptr}, enc_conv2_{nullptr}, enc_conv3_{nullptr},
      enc_conv4_{nullptr}, enc_conv5a_{nullptr}, enc_conv5b_{nullptr};
  torch::nn::Conv2d dec_conv4a_{nullptr}, dec_conv4b_{nullptr}, dec_conv3a_{nullptr}, dec_conv3b_{nullptr},
      dec_conv2a_{nullptr}, dec_conv2b_{nullptr}, dec_conv1a_{nullptr}, dec_conv1b_{nullptr}, dec_conv0_{nullptr};
};
TORCH_MODULE(DenoisingUNet);

}  // namespace matlearn
