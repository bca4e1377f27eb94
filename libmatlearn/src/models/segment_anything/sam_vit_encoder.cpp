#include "matlearn/models/segment_anything/sam_vit_encoder.h"

#include <algorithm>
#include <cmath>

#include "matlearn/models/segment_anything/layer_norm_2d.h"
#include "models/window_partition.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

constexpr double kLayerNormEps = 1e-6;

nn::LayerNorm layer_norm(int64_t dim) { return nn::LayerNorm(nn::LayerNormOptions({dim}).eps(kLayerNormEps)); }

// The table row of every (query, key) pair of positions along one axis of `side` tokens: offset
// q - k + side - 1, in [0, 2 side - 2].
torch::Tensor relative_offsets(int64_t side) {
  const torch::Tensor positions = torch::arange(side, torch::kLong);
  return positions.view({side, 1}) - positions.view({1, side}) + (side - 1);
}

}  // namespace

SamVitAttentionImpl::SamVitAttentionImpl(int64_t dim, int64_t heads, int64_t side) : heads_(heads) {
  const int64_t head_dim = dim / heads;
  rel_pos_h_ = register_parameter("rel_pos_h", torch::zeros({2 * side - 1, head_dim}));
  rel_pos_w_ = register_parameter("rel_pos_w", torch::zeros({2 * side - 1, head_dim}));
  qkv_ = register_module("qkv", nn::Linear(dim, 3 * dim));
  proj_ = register_module("proj", nn::Linear(dim, dim));
}

torch::Tensor SamVitAttentionImpl::forward(const torch::Tensor& x) {
  const int64_t n = x.size(0), h = x.size(1), w = x.size(2), c = x.size(3), head_dim = c / heads_;
  // qkv's output channels are [q | k | v], each head's channels together.
  const torch::Tensor qkv = qkv_(x).reshape({n, h * w, 3, heads_, head_dim}).permute({2, 0, 3, 1, 4}).reshape({3, n * heads_, h * w, head_dim});
  const torch::Tensor q = qkv[0], k = qkv[1], v = qkv[2];
  torch::Tensor scores = torch::matmul(q * (1.0 / std::sqrt(static_cast<double>(head_dim))), k.transpose(-2, -1));
  // The relative position terms use the unscaled query: bias[q, k] = q . R_h[qy - ky] + q . R_w[qx - kx].
  const torch::Tensor r_h = rel_pos_h_.index({relative_offsets(h)});  // h x h x head_dim
  const torch::Tensor r_w = rel_pos_w_.index({relative_offsets(w)});
  const torch::Tensor grid_q = q.reshape({n * heads_, h, w, head_dim});
  const torch::Tensor bias_h = torch::einsum("bhwc,hkc->bhwk", {grid_q, r_h});
  const torch::Tensor bias_w = torch::einsum("bhwc,wkc->bhwk", {grid_q, r_w});
  scores = (scores.view({n * heads_, h, w, h, w}) + bias_h.unsqueeze(4) + bias_w.unsqueeze(3)).view({n * heads_, h * w, h * w});
  const torch::Tensor out = torch::matmul(torch::softmax(scores, -1), v);
  return proj_(out.view({n, heads_, h, w, head_dim}).permute({0, 2, 3, 1, 4}).reshape({n, h, w, c}));
}

SamVitBlockImpl::SamVitBlockImpl(int64_t dim, int64_t heads, int64_t window, int64_t grid) : window_(window) {
  norm1_ = register_module("norm1", layer_norm(dim));
  attn_ = register_module("attn", SamVitAttention(dim, heads, window > 0 ? window : grid));
  norm2_ = register_module("norm2", layer_norm(dim));
  nn::Sequential mlp;
  mlp->push_back("lin1", nn::Linear(dim, 4 * dim));
  mlp->push_back("act", nn::GELU());
  mlp->push_back("lin2", nn::Linear(4 * dim, dim));
  mlp_ = register_module("mlp", mlp);
}

torch::Tensor SamVitBlockImpl::forward(const torch::Tensor& x) {
  torch::Tensor y = norm1_(x);
  if (window_ > 0) {
    // Windows of window x window tokens, the grid zero-padded at the bottom and right (the padded
    // tokens take part in the attention, as in the official encoder).
    const int64_t n = y.size(0), h = y.size(1), w = y.size(2), c = y.size(3);
    y = padded_to_windows(y, window_);
    const int64_t padded_h = y.size(1), padded_w = y.size(2);
    y = attn_(partition_windows(y, window_).view({-1, window_, window_, c}));
    y = merge_windows(y, n, padded_h, padded_w, window_).slice(1, 0, h).slice(2, 0, w);
  } else {
    y = attn_(y);
  }
  const torch::Tensor z = x + y;
  return z + mlp_->forward(norm2_(z));
}

SamVitEncoderImpl::SamVitEncoderImpl(const SamVitConfig& config) {
  const int64_t grid = config.grid();
  pos_embed_ = register_parameter("pos_embed", torch::zeros({1, grid, grid, config.dim}));
  // The official module tree names the patch convolution "patch_embed.proj".
  patch_embed_ = nn::Conv2d(nn::Conv2dOptions(3, config.dim, config.patch).stride(config.patch));
  auto patch_embed = std::make_shared<nn::Module>();
  patch_embed->register_module("proj", patch_embed_);
  register_module("patch_embed", patch_embed);
  blocks_ = register_module("blocks", nn::ModuleList());
  for (int64_t k = 0; k < config.depth; ++k) {
    const bool global = std::find(config.global_blocks.begin(), config.global_blocks.end(), k) != config.global_blocks.end();
    blocks_->push_back(SamVitBlock(config.dim, config.heads, global ? 0 : config.window, grid));
  }
  neck_ = register_module(
      "neck", nn::Sequential(nn::Conv2d(nn::Conv2dOptions(config.dim, config.out_channels, 1).bias(false)),
                             LayerNorm2d(config.out_channels),
                             nn::Conv2d(nn::Conv2dOptions(config.out_channels, config.out_channels, 3).padding(1).bias(false)),
                             LayerNorm2d(config.out_channels)));
}

torch::Tensor SamVitEncoderImpl::forward(const torch::Tensor& image) {
  torch::Tensor x = patch_embed_(image).permute({0, 2, 3, 1}) + pos_embed_;
  for (const auto& block : *blocks_) x = block->as<SamVitBlock>()->forward(x);
  return neck_->forward(x.permute({0, 3, 1, 2}));
}

}  // namespace matlearn
