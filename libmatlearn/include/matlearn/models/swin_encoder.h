#pragma once
// The Swin-T trunk (Liu et al. 2021, "Swin Transformer: Hierarchical Vision Transformer using
// Shifted Windows"), laid out exactly as torchvision 0.14's swin_t without its classifier: the
// module tree "features.0" (4x4 patch embedding + LayerNorm), "features.1, 3, 5, 7" (stages of 2,
// 2, 6, 2 blocks with 3, 6, 12, 24 heads), "features.2, 4, 6" (patch merging) and the final
// "norm", so torchvision's parameter and buffer names and shapes are ours and its state dict loads
// unchanged (27,519,354 parameters). Tokens are NHWC inside, as in torchvision.
#include <array>
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

// Window multi-head self-attention with a learned relative position bias (section 3.2 of the
// paper), over 7x7 windows that are cyclically shifted by half a window in every second block;
// the mask keeps tokens that the shift brought together from attending to each other. Inputs
// whose sides are not multiples of the window are padded at the bottom and right, as torchvision.
class ShiftedWindowAttentionImpl : public torch::nn::Module {
 public:
  ShiftedWindowAttentionImpl(int64_t dim, int64_t heads, int64_t window, bool shifted);
  torch::Tensor forward(const torch::Tensor& tokens);  // N x H x W x C

 private:
  torch::Tensor relative_position_bias() const;  // 1 x heads x window^2 x window^2
  torch::Tensor shift_mask(int64_t padded_height, int64_t padded_width, int64_t shift_h, int64_t shift_w) const;

  int64_t heads_, window_;
  bool shifted_;
  torch::nn::Linear qkv_{nullptr}, proj_{nullptr};
  torch::Tensor relative_position_bias_table_, relative_position_index_;
};
TORCH_MODULE(ShiftedWindowAttention);

// Pre-norm transformer block: x + attn(norm1(x)), then x + mlp(norm2(x)), MLP ratio 4 with GELU;
// each residual branch under stochastic depth.
class SwinBlockImpl : public torch::nn::Module {
 public:
  SwinBlockImpl(int64_t dim, int64_t heads, bool shifted, double drop_probability);
  torch::Tensor forward(const torch::Tensor& tokens);

 private:
  double drop_probability_;
  torch::nn::LayerNorm norm1_{nullptr}, norm2_{nullptr};
  ShiftedWindowAttention attn_{nullptr};
  torch::nn::Sequential mlp_{nullptr};
};
TORCH_MODULE(SwinBlock);

// Halves the resolution: each 2x2 token group concatenated (4C), LayerNorm, linear to 2C.
class PatchMergingImpl : public torch::nn::Module {
 public:
  explicit PatchMergingImpl(int64_t dim);
  torch::Tensor forward(const torch::Tensor& tokens);

 private:
  torch::nn::LayerNorm norm_{nullptr};
  torch::nn::Linear reduction_{nullptr};
};
TORCH_MODULE(PatchMerging);

// The four stages' outputs, NCHW; for a 224 input 96@56, 192@28, 384@14 and, after the final
// LayerNorm, 768@7.
struct SwinFeatures {
  std::array<torch::Tensor, 4> stages;
};

class SwinTEncoderImpl : public torch::nn::Module {
 public:
  SwinTEncoderImpl();
  SwinFeatures forward(const torch::Tensor& image);

 private:
  torch::nn::ModuleList features_{nullptr};
  torch::nn::LayerNorm norm_{nullptr};
};
TORCH_MODULE(SwinTEncoder);

}  // namespace matlearn
