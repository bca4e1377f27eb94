#pragma once
// Segment Anything's ViT image encoder (Kirillov et al. 2023, appendix A; Li et al. 2022,
// "Exploring Plain Vision Transformer Backbones for Object Detection"): 16 x 16 patches of the
// 1024 x 1024 input as 64 x 64 tokens with a learned absolute position, transformer blocks that
// attend within 14 x 14 windows except a few that attend globally, all with decomposed relative
// positions, and a neck to 256 channels. Laid out as the official "image_encoder" of vit_b
// (89,670,912 parameters). Tokens are N x H x W x C inside.
#include <cstdint>
#include <vector>

#include <torch/torch.h>

namespace matlearn {

struct SamVitConfig {
  int64_t image_side = 1024;
  int64_t patch = 16;
  int64_t dim = 768;
  int64_t depth = 12;
  int64_t heads = 12;
  int64_t window = 14;
  std::vector<int64_t> global_blocks = {2, 5, 8, 11};
  int64_t out_channels = 256;

  static SamVitConfig vit_b() { return {}; }
  int64_t grid() const { return image_side / patch; }
};

// Multi-head attention over an h x w grid of tokens with a learned bias per relative row and per
// relative column offset, each a function of the query (the "decomposed" relative positions of
// Li et al. 2022, section 3).
class SamVitAttentionImpl : public torch::nn::Module {
 public:
  SamVitAttentionImpl(int64_t dim, int64_t heads, int64_t side);
  torch::Tensor forward(const torch::Tensor& x);  // N x side x side x C

 private:
  int64_t heads_;
  torch::nn::Linear qkv_{nullptr}, proj_{nullptr};
  torch::Tensor rel_pos_h_, rel_pos_w_;
};
TORCH_MODULE(SamVitAttention);

// Pre-norm block: x + attention(norm1(x)) within windows (zero-padded to whole windows) or over
// the whole grid, then x + mlp(norm2(x)).
class SamVitBlockImpl : public torch::nn::Module {
 public:
  SamVitBlockImpl(int64_t dim, int64_t heads, int64_t window, int64_t grid);  // window 0: global
  torch::Tensor forward(const torch::Tensor& x);

 private:
  int64_t window_;
  torch::nn::LayerNorm norm1_{nullptr}, norm2_{nullptr};
  SamVitAttention attn_{nullptr};
  torch::nn::Sequential mlp_{nullptr};
};
TORCH_MODULE(SamVitBlock);

class SamVitEncoderImpl : public torch::nn::Module {
 public:
  explicit SamVitEncoderImpl(const SamVitConfig& config = SamVitConfig::vit_b());
  // N x 3 x side x side, normalised and padded, to N x 256 x grid x grid.
  torch::Tensor forward(const torch::Tensor& image);

 private:
  torch::Tensor pos_embed_;
  torch::nn::Conv2d patch_embed_{nullptr};
  torch::nn::ModuleList blocks_{nullptr};
  torch::nn::Sequential neck_{nullptr};
};
TORCH_MODULE(SamVitEncoder);

}  // namespace matlearn
