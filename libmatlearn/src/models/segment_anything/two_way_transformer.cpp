#include "matlearn/models/segment_anything/two_way_transformer.h"

#include <cmath>

namespace matlearn {
namespace {

namespace nn = torch::nn;

constexpr double kLayerNormEps = 1e-5;
constexpr int64_t kCrossAttentionDownsample = 2;

nn::LayerNorm layer_norm(int64_t dim) { return nn::LayerNorm(nn::LayerNormOptions({dim}).eps(kLayerNormEps)); }

}  // namespace

SamAttentionImpl::SamAttentionImpl(int64_t dim, int64_t heads, int64_t downsample) : heads_(heads) {
  const int64_t inner = dim / downsample;
  q_proj_ = register_module("q_proj", nn::Linear(dim, inner));
  k_proj_ = register_module("k_proj", nn::Linear(dim, inner));
  v_proj_ = register_module("v_proj", nn::Linear(dim, inner));
  out_proj_ = register_module("out_proj", nn::Linear(inner, dim));
}

torch::Tensor SamAttentionImpl::forward(const torch::Tensor& queries, const torch::Tensor& keys, const torch::Tensor& values) {
  const auto heads_of = [this](const torch::Tensor& x) {  // B x N x C -> B x heads x N x C/heads
    return x.view({x.size(0), x.size(1), heads_, x.size(2) / heads_}).transpose(1, 2);
  };
  const torch::Tensor q = heads_of(q_proj_(queries)), k = heads_of(k_proj_(keys)), v = heads_of(v_proj_(values));
  const torch::Tensor weights = torch::softmax(torch::matmul(q, k.transpose(2, 3)) / std::sqrt(static_cast<double>(q.size(3))), -1);
  const torch::Tensor out = torch::matmul(weights, v).transpose(1, 2);
  return out_proj_(out.reshape({out.size(0), out.size(1), -1}));
}

TwoWayAttentionBlockImpl::TwoWayAttentionBlockImpl(int64_t dim, int64_t heads, int64_t mlp_dim, bool first) : first_(first) {
  self_attn_ = register_module("self_attn", SamAttention(dim, heads));
  norm1_ = register_module("norm1", layer_norm(dim));
  token_to_image_ = register_module("cross_attn_token_to_image", SamAttention(dim, heads, kCrossAttentionDownsample));
  norm2_ = register_module("norm2", layer_norm(dim));
  nn::Sequential mlp;
  mlp->push_back("lin1", nn::Linear(dim, mlp_dim));
  mlp->push_back("act", nn::ReLU());
  mlp->push_back("lin2", nn::Linear(mlp_dim, dim));
  mlp_ = register_module("mlp", mlp);
  norm3_ = register_module("norm3", layer_norm(dim));
  norm4_ = register_module("norm4", layer_norm(dim));
  image_to_token_ = register_module("cross_attn_image_to_token", SamAttention(dim, heads, kCrossAttentionDownsample));
}

std::pair<torch::Tensor, torch::Tensor> TwoWayAttentionBlockImpl::forward(torch::Tensor queries, torch::Tensor keys,
                                                                          const torch::Tensor& query_pe,
                                                                          const torch::Tensor& key_pe) {
  if (first_) {
    queries = self_attn_(queries, queries, queries);
  } else {
    const torch::Tensor q = queries + query_pe;
    queries = queries + self_attn_(q, q, queries);
  }
  queries = norm1_(queries);
  queries = norm2_(queries + token_to_image_(queries + query_pe, keys + key_pe, keys));
  queries = norm3_(queries + mlp_->forward(queries));
  keys = norm4_(keys + image_to_token_(keys + key_pe, queries + query_pe, queries));
  return {queries, keys};
}

TwoWayTransformerImpl::TwoWayTransformerImpl(int64_t depth, int64_t dim, int64_t heads, int64_t mlp_dim) {
  layers_ = register_module("layers", nn::ModuleList());
  for (int64_t k = 0; k < depth; ++k) layers_->push_back(TwoWayAttentionBlock(dim, heads, mlp_dim, k == 0));
  final_attention_ = register_module("final_attn_token_to_image", SamAttention(dim, heads, kCrossAttentionDownsample));
  final_norm_ = register_module("norm_final_attn", layer_norm(dim));
}

std::pair<torch::Tensor, torch::Tensor> TwoWayTransformerImpl::forward(const torch::Tensor& image, const torch::Tensor& image_pe,
                                                                       const torch::Tensor& tokens) {
  torch::Tensor keys = image.flatten(2).permute({0, 2, 1});
  const torch::Tensor key_pe = image_pe.flatten(2).permute({0, 2, 1});
  torch::Tensor queries = tokens;
  for (const auto& layer : *layers_) {
    auto [q, k] = layer->as<TwoWayAttentionBlock>()->forward(queries, keys, tokens, key_pe);
    queries = q;
    keys = k;
  }
  queries = final_norm_(queries + final_attention_(queries + tokens, keys + key_pe, keys));
  return {queries, keys};
}

}  // namespace matlearn
