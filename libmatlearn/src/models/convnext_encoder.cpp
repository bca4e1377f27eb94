#include "matlearn/models/convnext_encoder.h"

#include "matlearn/models/stochastic_depth.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

constexpr std::array<int64_t, 4> kDepths = {3, 3, 9, 3};
constexpr std::array<int64_t, 4> kWidths = {96, 192, 384, 768};
constexpr double kMaxDropProbability = 0.1;  // torchvision's convnext_tiny
constexpr double kLayerScale = 1e-6;         // initial value of every block's layer scale
constexpr double kLayerNormEps = 1e-6;

// torchvision initialises convolutions and linears with a normal of std 0.02 truncated at +-2,
// 100 standard deviations out (so a plain normal), and zero biases.
void init_weights(nn::Module& module) {
  torch::NoGradGuard no_grad;
  for (auto& m : module.modules(/*include_self=*/false)) {
    if (auto* conv = m->as<nn::Conv2d>()) {
      conv->weight.normal_(0.0, 0.02);
      conv->bias.zero_();
    } else if (auto* linear = m->as<nn::Linear>()) {
      linear->weight.normal_(0.0, 0.02);
      linear->bias.zero_();
    }
  }
}

}  // namespace

ChannelLayerNormImpl::ChannelLayerNormImpl(int64_t channels) {
  weight_ = register_parameter("weight", torch::ones({channels}));
  bias_ = register_parameter("bias", torch::zeros({channels}));
}

torch::Tensor ChannelLayerNormImpl::forward(const torch::Tensor& x) {
  return torch::layer_norm(x.permute({0, 2, 3, 1}), {weight_.size(0)}, weight_, bias_, kLayerNormEps)
      .permute({0, 3, 1, 2});
}

ConvNeXtBlockImpl::ConvNeXtBlockImpl(int64_t channels, double drop_probability) : drop_probability_(drop_probability) {
  block_ = register_module(
      "block",
      nn::Sequential(nn::Conv2d(nn::Conv2dOptions(channels, channels, 7).padding(3).groups(channels)),
                     nn::Functional([](const torch::Tensor& x) { return x.permute({0, 2, 3, 1}); }),
                     nn::LayerNorm(nn::LayerNormOptions({channels}).eps(kLayerNormEps)),
                     nn::Linear(channels, 4 * channels), nn::GELU(), nn::Linear(4 * channels, channels),
                     nn::Functional([](const torch::Tensor& x) { return x.permute({0, 3, 1, 2}); })));
  layer_scale_ = register_parameter("layer_scale", torch::full({channels, 1, 1}, kLayerScale));
}

torch::Tensor ConvNeXtBlockImpl::forward(const torch::Tensor& x) {
  return x + drop_residual_rows(layer_scale_ * block_->forward(x), drop_probability_, is_training());
}

ConvNeXtTEncoderImpl::ConvNeXtTEncoderImpl() {
  features_ = register_module("features", nn::ModuleList());
  features_->push_back(
      nn::Sequential(nn::Conv2d(nn::Conv2dOptions(3, kWidths[0], 4).stride(4)), ChannelLayerNorm(kWidths[0])));
  const int64_t blocks = kDepths[0] + kDepths[1] + kDepths[2] + kDepths[3];
  int64_t block = 0;
  for (size_t s = 0; s < kDepths.size(); ++s) {
    nn::Sequential stage;
    for (int64_t b = 0; b < kDepths[s]; ++b, ++block)
      stage->push_back(ConvNeXtBlock(kWidths[s], block_drop_probability(kMaxDropProbability, block, blocks)));
    features_->push_back(stage);
    if (s + 1 < kDepths.size())
      features_->push_back(nn::Sequential(ChannelLayerNorm(kWidths[s]),
                                          nn::Conv2d(nn::Conv2dOptions(kWidths[s], kWidths[s + 1], 2).stride(2))));
  }
  init_weights(*this);
}

ConvNeXtFeatures ConvNeXtTEncoderImpl::forward(const torch::Tensor& image) {
  ConvNeXtFeatures f;
  torch::Tensor x = image;
  // features.0 embeds; then stage, downsample, stage, downsample, stage, downsample, stage.
  for (size_t i = 0; i < features_->size(); ++i) {
    x = features_[i]->as<nn::Sequential>()->forward(x);
    if (i % 2 == 1) f.stages[i / 2] = x;
  }
  return f;
}

}  // namespace matlearn
