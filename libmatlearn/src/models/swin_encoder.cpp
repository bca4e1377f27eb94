#include "matlearn/models/swin_encoder.h"

#include <cmath>

#include "matlearn/models/stochastic_depth.h"
#include "models/window_partition.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

constexpr int64_t kEmbedDim = 96;
constexpr int64_t kWindow = 7;
constexpr std::array<int64_t, 4> kDepths = {2, 2, 6, 2};
constexpr std::array<int64_t, 4> kHeads = {3, 6, 12, 24};
constexpr double kMaxDropProbability = 0.2;  // torchvision's swin_t
constexpr double kLayerNormEps = 1e-5;

nn::LayerNorm layer_norm(int64_t dim) { return nn::LayerNorm(nn::LayerNormOptions({dim}).eps(kLayerNormEps)); }

// torchvision initialises every Linear of Swin with a normal of std 0.02 truncated at +-2, 100
// standard deviations out, so a plain normal draws the same distribution.
void init_linear(nn::Linear& linear) {
  torch::NoGradGuard no_grad;
  linear->weight.normal_(0.0, 0.02);
  if (linear->bias.defined()) linear->bias.zero_();
}

// Index into the (2w-1)^2 bias table for every pair of positions i, j in a w x w window:
// (dy + w - 1) * (2w - 1) + (dx + w - 1) with (dy, dx) = position i - position j.
torch::Tensor relative_position_index(int64_t window) {
  const int64_t n = window * window;
  torch::Tensor index = torch::empty({n * n}, torch::kLong);
  auto out = index.accessor<int64_t, 1>();
  for (int64_t i = 0; i < n; ++i)
    for (int64_t j = 0; j < n; ++j) {
      const int64_t dy = i / window - j / window, dx = i % window - j % window;
      out[i * n + j] = (dy + window - 1) * (2 * window - 1) + (dx + window - 1);
    }
  return index;
}

}  // namespace

ShiftedWindowAttentionImpl::ShiftedWindowAttentionImpl(int64_t dim, int64_t heads, int64_t window, bool shifted)
    : heads_(heads), window_(window), shifted_(shifted) {
  qkv_ = register_module("qkv", nn::Linear(dim, 3 * dim));
  proj_ = register_module("proj", nn::Linear(dim, dim));
  init_linear(qkv_);
  init_linear(proj_);
  relative_position_bias_table_ = register_parameter(
      "relative_position_bias_table", torch::randn({(2 * window - 1) * (2 * window - 1), heads}) * 0.02);
  relative_position_index_ = register_buffer("relative_position_index", relative_position_index(window));
}

torch::Tensor ShiftedWindowAttentionImpl::relative_position_bias() const {
  const int64_t n = window_ * window_;
  return relative_position_bias_table_.index_select(0, relative_position_index_)
      .view({n, n, heads_})
      .permute({2, 0, 1})
      .unsqueeze(0);
}

// Region ids of the padded grid after the roll: rows (and columns) split at -window and -shift
// into three bands; tokens of different regions in one window must not attend to each other.
torch::Tensor ShiftedWindowAttentionImpl::shift_mask(int64_t padded_height, int64_t padded_width, int64_t shift_h,
                                                     int64_t shift_w) const {
  auto band = [this](int64_t p, int64_t size, int64_t shift) -> int64_t {
    if (p < size - window_) return 0;
    return p < size - shift ? 1 : 2;
  };
  torch::Tensor region = torch::empty({1, padded_height, padded_width, 1});
  auto r = region.accessor<float, 4>();
  for (int64_t y = 0; y < padded_height; ++y)
    for (int64_t x = 0; x < padded_width; ++x)
      r[0][y][x][0] = static_cast<float>(3 * band(y, padded_height, shift_h) + band(x, padded_width, shift_w));
  const torch::Tensor ids = partition_windows(region, window_).squeeze(-1);  // windows x w^2
  const torch::Tensor different = ids.unsqueeze(1) != ids.unsqueeze(2);
  // -100 as torchvision: after the softmax such pairs weigh exp(-100) relative to the others.
  return torch::zeros(different.sizes()).masked_fill(different, -100.0);
}

torch::Tensor ShiftedWindowAttentionImpl::forward(const torch::Tensor& tokens) {
  const int64_t batch = tokens.size(0), height = tokens.size(1), width = tokens.size(2), dim = tokens.size(3);
  torch::Tensor x = padded_to_windows(tokens, window_);
  const int64_t padded_height = x.size(1), padded_width = x.size(2);
  // A grid no larger than the window has nothing to shift along that axis.
  const int64_t shift_h = shifted_ && padded_height > window_ ? window_ / 2 : 0;
  const int64_t shift_w = shifted_ && padded_width > window_ ? window_ / 2 : 0;
  const bool shift = shift_h + shift_w > 0;
  if (shift) x = torch::roll(x, {-shift_h, -shift_w}, {1, 2});

  x = partition_windows(x, window_);
  const int64_t windows = x.size(0), n = x.size(1), head_dim = dim / heads_;
  const torch::Tensor qkv = qkv_->forward(x).reshape({windows, n, 3, heads_, head_dim}).permute({2, 0, 3, 1, 4});
  const torch::Tensor q = qkv[0] * (1.0 / std::sqrt(static_cast<double>(head_dim)));
  torch::Tensor attention = q.matmul(qkv[1].transpose(-2, -1)) + relative_position_bias();
  if (shift) {
    const int64_t per_image = windows / batch;
    attention = (attention.view({batch, per_image, heads_, n, n}) +
                 shift_mask(padded_height, padded_width, shift_h, shift_w).unsqueeze(1).unsqueeze(0))
                    .view({-1, heads_, n, n});
  }
  x = torch::softmax(attention, -1).matmul(qkv[2]).transpose(1, 2).reshape({windows, n, dim});
  x = merge_windows(proj_->forward(x), batch, padded_height, padded_width, window_);
  if (shift) x = torch::roll(x, {shift_h, shift_w}, {1, 2});
  return x.slice(1, 0, height).slice(2, 0, width).contiguous();
}

SwinBlockImpl::SwinBlockImpl(int64_t dim, int64_t heads, bool shifted, double drop_probability)
    : drop_probability_(drop_probability) {
  norm1_ = register_module("norm1", layer_norm(dim));
  attn_ = register_module("attn", ShiftedWindowAttention(dim, heads, kWindow, shifted));
  norm2_ = register_module("norm2", layer_norm(dim));
  // torchvision's MLP: Linear, GELU, Dropout, Linear, Dropout (so the linears are "0" and "3").
  nn::Linear expand(dim, 4 * dim), contract(4 * dim, dim);
  init_linear(expand);
  init_linear(contract);
  mlp_ = register_module("mlp", nn::Sequential(expand, nn::GELU(), nn::Dropout(0.0), contract, nn::Dropout(0.0)));
}

torch::Tensor SwinBlockImpl::forward(const torch::Tensor& tokens) {
  torch::Tensor x = tokens + drop_residual_rows(attn_->forward(norm1_->forward(tokens)), drop_probability_, is_training());
  return x + drop_residual_rows(mlp_->forward(norm2_->forward(x)), drop_probability_, is_training());
}

PatchMergingImpl::PatchMergingImpl(int64_t dim) {
  reduction_ = register_module("reduction", nn::Linear(nn::LinearOptions(4 * dim, 2 * dim).bias(false)));
  norm_ = register_module("norm", layer_norm(4 * dim));
  init_linear(reduction_);
}

torch::Tensor PatchMergingImpl::forward(const torch::Tensor& tokens) {
  // Odd sides are padded by one token; the 2x2 group is concatenated in torchvision's order
  // (0,0), (1,0), (0,1), (1,1) so that its reduction weights apply.
  const torch::Tensor x = torch::constant_pad_nd(tokens, {0, 0, 0, tokens.size(2) % 2, 0, tokens.size(1) % 2});
  using torch::indexing::None;
  using torch::indexing::Slice;
  const torch::Tensor merged = torch::cat({x.index({Slice(), Slice(0, None, 2), Slice(0, None, 2)}),
                                           x.index({Slice(), Slice(1, None, 2), Slice(0, None, 2)}),
                                           x.index({Slice(), Slice(0, None, 2), Slice(1, None, 2)}),
                                           x.index({Slice(), Slice(1, None, 2), Slice(1, None, 2)})},
                                          -1);
  return reduction_->forward(norm_->forward(merged));
}

SwinTEncoderImpl::SwinTEncoderImpl() {
  features_ = register_module("features", nn::ModuleList());
  features_->push_back(nn::Sequential(
      nn::Conv2d(nn::Conv2dOptions(3, kEmbedDim, 4).stride(4)),
      nn::Functional([](const torch::Tensor& x) { return x.permute({0, 2, 3, 1}); }), layer_norm(kEmbedDim)));
  const int64_t blocks = kDepths[0] + kDepths[1] + kDepths[2] + kDepths[3];
  int64_t block = 0, dim = kEmbedDim;
  for (size_t s = 0; s < kDepths.size(); ++s) {
    nn::Sequential stage;
    for (int64_t b = 0; b < kDepths[s]; ++b, ++block)
      stage->push_back(SwinBlock(dim, kHeads[s], b % 2 == 1, block_drop_probability(kMaxDropProbability, block, blocks)));
    features_->push_back(stage);
    if (s + 1 < kDepths.size()) {
      features_->push_back(PatchMerging(dim));
      dim *= 2;
    }
  }
  norm_ = register_module("norm", layer_norm(dim));
}

SwinFeatures SwinTEncoderImpl::forward(const torch::Tensor& image) {
  SwinFeatures f;
  torch::Tensor x = image;
  // features.0 embeds; then stage, merge, stage, merge, stage, merge, stage.
  for (size_t i = 0; i < features_->size(); ++i) {
    x = features_[i]->as<nn::Sequential>() ? features_[i]->as<nn::Sequential>()->forward(x)
                                           : features_[i]->as<PatchMerging>()->forward(x);
    if (i % 2 == 1) {
      const size_t stage = i / 2;
      f.stages[stage] = (stage == 3 ? norm_->forward(x) : x).permute({0, 3, 1, 2});
    }
  }
  return f;
}

}  // namespace matlearn
