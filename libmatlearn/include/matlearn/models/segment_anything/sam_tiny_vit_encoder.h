#pragma once
// MobileSAM's image encoder (Zhang et al. 2023, "Faster Segment Anything"): TinyViT-5M (Wu et
// al. 2022, "TinyViT: Fast Pretraining Distillation for Small Vision Transformers") distilled from
// SAM's ViT-H, which turns the 1024 input into the same 256 x 64 x 64 embedding with 6 % of ViT-B's
// weights. A convolutional stem and stage of inverted residual blocks (MBConv), then three stages
// of windowed attention with a learned bias per absolute row and column offset, each followed by
// a depthwise convolution; patch merging between stages; SAM's neck. Laid out as the official
// "image_encoder" of vit_t (6,065,532 parameters, its unused 1000-class head included so that
// the released checkpoint loads unchanged). BatchNorms run on their running statistics: call
// eval() before use.
#include <cstdint>
#include <memory>

#include <torch/torch.h>

namespace matlearn {

// Attention within a window x window of tokens: LayerNorm, per-head q, k, v of 32 channels, and
// a bias per head for each (|dy|, |dx|) offset between two tokens (TinyViT's section 3).
class TinyVitAttentionImpl : public torch::nn::Module {
 public:
  TinyVitAttentionImpl(int64_t dim, int64_t heads, int64_t window);
  torch::Tensor forward(const torch::Tensor& tokens);  // windows x window^2 x C

 private:
  int64_t heads_, key_dim_;
  torch::nn::LayerNorm norm_{nullptr};
  torch::nn::Linear qkv_{nullptr}, proj_{nullptr};
  torch::Tensor attention_biases_;
  torch::Tensor bias_index_;  // window^2 x window^2: |dy| window + |dx|; derived, not a weight
};
TORCH_MODULE(TinyVitAttention);

// Windowed attention with a residual, a depthwise 3 x 3 convolution with BatchNorm (no residual),
// then an MLP (LayerNorm first) with a residual, on the side x side grid of B x side^2 x C tokens.
class TinyVitBlockImpl : public torch::nn::Module {
 public:
  TinyVitBlockImpl(int64_t dim, int64_t heads, int64_t window, int64_t side);
  torch::Tensor forward(const torch::Tensor& tokens);

 private:
  int64_t window_, side_;
  TinyVitAttention attn_{nullptr};
  torch::nn::Sequential mlp_norm_and_layers_{nullptr};
  std::shared_ptr<torch::nn::Module> local_conv_;  // a convolution and its BatchNorm (Conv2d_BN)
};
TORCH_MODULE(TinyVitBlock);

class SamTinyVitEncoderImpl : public torch::nn::Module {
 public:
  SamTinyVitEncoderImpl();
  // N x 3 x 1024 x 1024, normalised and padded, to N x 256 x 64 x 64.
  torch::Tensor forward(const torch::Tensor& image);

 private:
  torch::nn::Sequential patch_embed_{nullptr};
  torch::nn::ModuleList layers_{nullptr};
  torch::nn::Sequential neck_{nullptr};
};
TORCH_MODULE(SamTinyVitEncoder);

}  // namespace matlearn
