#include "matlearn/models/segment_anything/sam_tiny_vit_encoder.h"

#include <array>
#include <cmath>

#include "matlearn/models/segment_anything/layer_norm_2d.h"
#include "models/window_partition.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

// TinyViT-5M as MobileSAM configures it.
constexpr std::array<int64_t, 4> kDims = {64, 128, 160, 320};
constexpr std::array<int64_t, 4> kDepths = {2, 2, 6, 2};
constexpr std::array<int64_t, 4> kHeads = {2, 4, 5, 10};  // stage 0 is convolutional: unused
constexpr std::array<int64_t, 4> kWindows = {7, 7, 14, 7};
constexpr int64_t kExpand = 4;          // MBConv's hidden channels and the MLPs' ratio
constexpr int64_t kStemSide = 256;      // 1024 / 4 after the stem
constexpr int64_t kOutputSide = 64;     // the last two stages' grid
constexpr int64_t kHeadClasses = 1000;  // the unused classifier's
constexpr int64_t kNeckChannels = 256;

// A convolution without bias followed by a BatchNorm: the official Conv2d_BN, children "c", "bn".
class ConvBnImpl : public nn::Module {
 public:
  ConvBnImpl(int64_t in, int64_t out, int64_t kernel, int64_t stride = 1, int64_t padding = 0, int64_t groups = 1) {
    c_ = register_module("c", nn::Conv2d(nn::Conv2dOptions(in, out, kernel).stride(stride).padding(padding).groups(groups).bias(false)));
    bn_ = register_module("bn", nn::BatchNorm2d(out));
  }
  torch::Tensor forward(const torch::Tensor& x) { return bn_(c_(x)); }

 private:
  nn::Conv2d c_{nullptr};
  nn::BatchNorm2d bn_{nullptr};
};
TORCH_MODULE(ConvBn);

// Sandler et al. 2018's inverted residual: expand 1x1, depthwise 3x3, project 1x1, add the input,
// then GELU (after the sum, as TinyViT).
class MbConvImpl : public nn::Module {
 public:
  explicit MbConvImpl(int64_t dim) {
    conv1_ = register_module("conv1", ConvBn(dim, kExpand * dim, 1));
    conv2_ = register_module("conv2", ConvBn(kExpand * dim, kExpand * dim, 3, 1, 1, kExpand * dim));
    conv3_ = register_module("conv3", ConvBn(kExpand * dim, dim, 1));
  }
  torch::Tensor forward(const torch::Tensor& x) {
    const torch::Tensor y = conv3_(torch::gelu(conv2_(torch::gelu(conv1_(x)))));
    return torch::gelu(x + y);
  }

 private:
  ConvBn conv1_{nullptr}, conv2_{nullptr}, conv3_{nullptr};
};
TORCH_MODULE(MbConv);

// B x C x H x W to B x (H/s W/s) x out: 1x1, depthwise 3x3 of stride s, 1x1; stride 1 into the
// last stage, so that it keeps the 64 x 64 grid.
class PatchMergingImpl : public nn::Module {
 public:
  PatchMergingImpl(int64_t dim, int64_t out) {
    const int64_t stride = out == kDims[3] ? 1 : 2;
    conv1_ = register_module("conv1", ConvBn(dim, out, 1));
    conv2_ = register_module("conv2", ConvBn(out, out, 3, stride, 1, out));
    conv3_ = register_module("conv3", ConvBn(out, out, 1));
  }
  torch::Tensor forward(const torch::Tensor& x) {
    const torch::Tensor y = conv3_(torch::gelu(conv2_(torch::gelu(conv1_(x)))));
    return y.flatten(2).transpose(1, 2);
  }

 private:
  ConvBn conv1_{nullptr}, conv2_{nullptr}, conv3_{nullptr};
};
TORCH_MODULE(PatchMerging);

// Stage 0: MBConv blocks on B x C x H x W, then patch merging to tokens.
class ConvStageImpl : public nn::Module {
 public:
  ConvStageImpl(int64_t dim, int64_t depth, int64_t out) {
    blocks_ = register_module("blocks", nn::ModuleList());
    for (int64_t k = 0; k < depth; ++k) blocks_->push_back(MbConv(dim));
    downsample_ = register_module("downsample", PatchMerging(dim, out));
  }
  torch::Tensor forward(torch::Tensor x) {
    for (const auto& block : *blocks_) x = block->as<MbConv>()->forward(x);
    return downsample_(x);
  }

 private:
  nn::ModuleList blocks_{nullptr};
  PatchMerging downsample_{nullptr};
};
TORCH_MODULE(ConvStage);

// Stages 1 to 3: TinyViT blocks on B x side^2 x C tokens, then patch merging but after the last.
class AttentionStageImpl : public nn::Module {
 public:
  AttentionStageImpl(int64_t dim, int64_t depth, int64_t heads, int64_t window, int64_t side, int64_t out) : side_(side) {
    blocks_ = register_module("blocks", nn::ModuleList());
    for (int64_t k = 0; k < depth; ++k) blocks_->push_back(TinyVitBlock(dim, heads, window, side));
    if (out > 0) downsample_ = register_module("downsample", PatchMerging(dim, out));
  }
  torch::Tensor forward(torch::Tensor x) {
    for (const auto& block : *blocks_) x = block->as<TinyVitBlock>()->forward(x);
    if (downsample_.is_empty()) return x;
    return downsample_(x.transpose(1, 2).reshape({x.size(0), x.size(2), side_, side_}));
  }

 private:
  int64_t side_;
  nn::ModuleList blocks_{nullptr};
  PatchMerging downsample_{nullptr};
};
TORCH_MODULE(AttentionStage);

// |dy| window + |dx| for every pair of positions of a window: TinyViT's offsets, numbered in the
// order its code first meets them, which is this row-major order.
torch::Tensor offset_index(int64_t window) {
  const int64_t n = window * window;
  torch::Tensor index = torch::empty({n, n}, torch::kLong);
  auto out = index.accessor<int64_t, 2>();
  for (int64_t i = 0; i < n; ++i)
    for (int64_t j = 0; j < n; ++j) out[i][j] = std::abs(i / window - j / window) * window + std::abs(i % window - j % window);
  return index;
}

}  // namespace

TinyVitAttentionImpl::TinyVitAttentionImpl(int64_t dim, int64_t heads, int64_t window)
    : heads_(heads), key_dim_(dim / heads) {
  norm_ = register_module("norm", nn::LayerNorm(nn::LayerNormOptions({dim})));
  qkv_ = register_module("qkv", nn::Linear(dim, 3 * dim));
  proj_ = register_module("proj", nn::Linear(dim, dim));
  attention_biases_ = register_parameter("attention_biases", torch::zeros({heads, window * window}));
  bias_index_ = offset_index(window);
}

torch::Tensor TinyVitAttentionImpl::forward(const torch::Tensor& tokens) {
  const int64_t b = tokens.size(0), n = tokens.size(1);
  // qkv's channels are per head [q k v], unlike SAM's ViT.
  const std::vector<torch::Tensor> qkv = qkv_(norm_(tokens)).view({b, n, heads_, 3 * key_dim_}).split(key_dim_, 3);
  const torch::Tensor q = qkv[0].permute({0, 2, 1, 3}), k = qkv[1].permute({0, 2, 1, 3}), v = qkv[2].permute({0, 2, 1, 3});
  const torch::Tensor bias = attention_biases_.index({torch::indexing::Slice(), bias_index_.to(attention_biases_.device())});
  const torch::Tensor scores = torch::matmul(q, k.transpose(-2, -1)) * (1.0 / std::sqrt(static_cast<double>(key_dim_))) + bias;
  const torch::Tensor out = torch::matmul(torch::softmax(scores, -1), v).transpose(1, 2).reshape({b, n, heads_ * key_dim_});
  return proj_(out);
}

TinyVitBlockImpl::TinyVitBlockImpl(int64_t dim, int64_t heads, int64_t window, int64_t side) : window_(window), side_(side) {
  attn_ = register_module("attn", TinyVitAttention(dim, heads, window));
  nn::Sequential mlp;
  mlp->push_back("norm", nn::LayerNorm(nn::LayerNormOptions({dim})));
  mlp->push_back("fc1", nn::Linear(dim, kExpand * dim));
  mlp->push_back("act", nn::GELU());
  mlp->push_back("fc2", nn::Linear(kExpand * dim, dim));
  mlp_norm_and_layers_ = register_module("mlp", mlp);
  local_conv_ = register_module("local_conv", ConvBn(dim, dim, 3, 1, 1, dim));
}

torch::Tensor TinyVitBlockImpl::forward(const torch::Tensor& tokens) {
  const int64_t b = tokens.size(0), c = tokens.size(2), s = side_, w = window_;
  torch::Tensor y;
  if (s == w) {
    y = attn_(tokens);
  } else {
    // Windows of the grid zero-padded at the bottom and right; the padded tokens are normalised
    // and attended to like the rest, as in the official encoder.
    y = padded_to_windows(tokens.view({b, s, s, c}), w);
    const int64_t padded = y.size(1);
    y = merge_windows(attn_(partition_windows(y, w)), b, padded, padded, w);
    y = y.slice(1, 0, s).slice(2, 0, s).reshape({b, s * s, c});
  }
  torch::Tensor x = tokens + y;
  x = local_conv_->as<ConvBnImpl>()->forward(x.transpose(1, 2).reshape({b, c, s, s})).view({b, c, s * s}).transpose(1, 2);
  return x + mlp_norm_and_layers_->forward(x);
}

SamTinyVitEncoderImpl::SamTinyVitEncoderImpl() {
  nn::Sequential stem;
  stem->push_back("0", ConvBn(3, kDims[0] / 2, 3, 2, 1));
  stem->push_back("1", nn::GELU());
  stem->push_back("2", ConvBn(kDims[0] / 2, kDims[0], 3, 2, 1));
  auto patch_embed = std::make_shared<nn::Module>();  // the official "patch_embed.seq"
  patch_embed_ = patch_embed->register_module("seq", stem);
  register_module("patch_embed", patch_embed);
  layers_ = register_module("layers", nn::ModuleList());
  layers_->push_back(ConvStage(kDims[0], kDepths[0], kDims[1]));
  int64_t side = kStemSide / 2;
  for (size_t k = 1; k < kDims.size(); ++k) {
    const bool last = k + 1 == kDims.size();
    layers_->push_back(AttentionStage(kDims[k], kDepths[k], kHeads[k], kWindows[k], side, last ? 0 : kDims[k + 1]));
    if (!last && kDims[k + 1] != kDims[3]) side /= 2;  // merging into the last stage keeps the grid
  }
  register_module("norm_head", nn::LayerNorm(nn::LayerNormOptions({kDims[3]})));
  register_module("head", nn::Linear(kDims[3], kHeadClasses));
  neck_ = register_module(
      "neck", nn::Sequential(nn::Conv2d(nn::Conv2dOptions(kDims[3], kNeckChannels, 1).bias(false)), LayerNorm2d(kNeckChannels),
                             nn::Conv2d(nn::Conv2dOptions(kNeckChannels, kNeckChannels, 3).padding(1).bias(false)),
                             LayerNorm2d(kNeckChannels)));
}

torch::Tensor SamTinyVitEncoderImpl::forward(const torch::Tensor& image) {
  torch::Tensor x = layers_[0]->as<ConvStage>()->forward(patch_embed_->forward(image));
  for (size_t k = 1; k < layers_->size(); ++k) x = layers_[k]->as<AttentionStage>()->forward(x);
  const int64_t b = x.size(0), c = x.size(2);
  return neck_->forward(x.view({b, kOutputSide, kOutputSide, c}).permute({0, 3, 1, 2}));
}

}  // namespace matlearn
