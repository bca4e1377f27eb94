#pragma once
// Segment Anything's two-way transformer (Kirillov et al. 2023, appendix A, "Lightweight mask
// decoder"): prompt tokens and image tokens attend to each other in both directions, twice, then
// the tokens attend to the image once more. Laid out as the official "mask_decoder.transformer".
#include <cstdint>
#include <utility>

#include <torch/torch.h>

namespace matlearn {

// Multi-head attention whose queries, keys and values are projected to dim / downsample channels
// (the cross-attentions' 128) and back.
class SamAttentionImpl : public torch::nn::Module {
 public:
  SamAttentionImpl(int64_t dim, int64_t heads, int64_t downsample = 1);
  torch::Tensor forward(const torch::Tensor& queries, const torch::Tensor& keys, const torch::Tensor& values);

 private:
  int64_t heads_;
  torch::nn::Linear q_proj_{nullptr}, k_proj_{nullptr}, v_proj_{nullptr}, out_proj_{nullptr};
};
TORCH_MODULE(SamAttention);

// One layer: tokens' self-attention (without positions or residual in the first layer), tokens
// to image, an MLP on the tokens, image to tokens; each followed by a LayerNorm.
class TwoWayAttentionBlockImpl : public torch::nn::Module {
 public:
  TwoWayAttentionBlockImpl(int64_t dim, int64_t heads, int64_t mlp_dim, bool first);
  // queries B x N x C and keys B x HW x C with their positional encodings; returns both updated.
  std::pair<torch::Tensor, torch::Tensor> forward(torch::Tensor queries, torch::Tensor keys, const torch::Tensor& query_pe,
                                                  const torch::Tensor& key_pe);

 private:
  bool first_;
  SamAttention self_attn_{nullptr}, token_to_image_{nullptr}, image_to_token_{nullptr};
  torch::nn::LayerNorm norm1_{nullptr}, norm2_{nullptr}, norm3_{nullptr}, norm4_{nullptr};
  torch::nn::Sequential mlp_{nullptr};
};
TORCH_MODULE(TwoWayAttentionBlock);

class TwoWayTransformerImpl : public torch::nn::Module {
 public:
  TwoWayTransformerImpl(int64_t depth = 2, int64_t dim = 256, int64_t heads = 8, int64_t mlp_dim = 2048);
  // image B x C x H x W and its encoding, tokens B x N x C: (tokens, image tokens B x HW x C).
  std::pair<torch::Tensor, torch::Tensor> forward(const torch::Tensor& image, const torch::Tensor& image_pe,
                                                  const torch::Tensor& tokens);

 private:
  torch::nn::ModuleList layers_{nullptr};
  SamAttention final_attention_{nullptr};
  torch::nn::LayerNorm final_norm_{nullptr};
};
TORCH_MODULE(TwoWayTransformer);

}  // namespace matlearn
