#include "matlearn/models/segment_anything/sam_mask_decoder.h"

#include <vector>

#include "matlearn/models/segment_anything/layer_norm_2d.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

constexpr int64_t kDim = 256;
constexpr int64_t kUpscaledChannels = kDim / 8;  // 32, after two 2x transposed convolutions

}  // namespace

SamMlpImpl::SamMlpImpl(int64_t in, int64_t hidden, int64_t out, int64_t layers) {
  layers_ = register_module("layers", nn::ModuleList());
  for (int64_t k = 0; k < layers; ++k)
    layers_->push_back(nn::Linear(k == 0 ? in : hidden, k + 1 == layers ? out : hidden));
}

torch::Tensor SamMlpImpl::forward(torch::Tensor x) {
  for (size_t k = 0; k < layers_->size(); ++k) {
    x = layers_[k]->as<nn::Linear>()->forward(x);
    if (k + 1 < layers_->size()) x = torch::relu(x);
  }
  return x;
}

SamMaskDecoderImpl::SamMaskDecoderImpl() {
  transformer_ = register_module("transformer", TwoWayTransformer());
  iou_token_ = register_module("iou_token", nn::Embedding(1, kDim));
  mask_tokens_ = register_module("mask_tokens", nn::Embedding(kMaskTokens, kDim));
  output_upscaling_ = register_module(
      "output_upscaling",
      nn::Sequential(nn::ConvTranspose2d(nn::ConvTranspose2dOptions(kDim, kDim / 4, 2).stride(2)), LayerNorm2d(kDim / 4),
                     nn::GELU(), nn::ConvTranspose2d(nn::ConvTranspose2dOptions(kDim / 4, kUpscaledChannels, 2).stride(2)),
                     nn::GELU()));
  hypernetworks_ = register_module("output_hypernetworks_mlps", nn::ModuleList());
  for (int64_t k = 0; k < kMaskTokens; ++k) hypernetworks_->push_back(SamMlp(kDim, kDim, kUpscaledChannels, 3));
  iou_head_ = register_module("iou_prediction_head", SamMlp(kDim, kDim, kMaskTokens, 3));
}

SamMasks SamMaskDecoderImpl::forward(const torch::Tensor& image, const torch::Tensor& image_pe, const torch::Tensor& sparse,
                                     const torch::Tensor& dense) {
  const int64_t batch = sparse.size(0);
  const torch::Tensor output_tokens = torch::cat({iou_token_->weight, mask_tokens_->weight}).unsqueeze(0).expand({batch, -1, -1});
  const torch::Tensor tokens = torch::cat({output_tokens, sparse}, 1);
  // One image for every prompt of the batch.
  const torch::Tensor source = (image.size(0) == batch ? image : image.expand({batch, -1, -1, -1})) + dense;
  const torch::Tensor source_pe = image_pe.expand({batch, -1, -1, -1});
  const auto [out_tokens, image_tokens] = transformer_(source, source_pe, tokens);

  const int64_t side = source.size(2);
  const torch::Tensor upscaled =
      output_upscaling_->forward(image_tokens.transpose(1, 2).reshape({batch, kDim, side, source.size(3)}));
  std::vector<torch::Tensor> weights;
  for (int64_t k = 0; k < kMaskTokens; ++k)
    weights.push_back(hypernetworks_[k]->as<SamMlp>()->forward(out_tokens.select(1, 1 + k)));
  const torch::Tensor hyper = torch::stack(weights, 1);  // B x 4 x 32
  const int64_t h = upscaled.size(2), w = upscaled.size(3);
  SamMasks masks;
  masks.logits = torch::matmul(hyper, upscaled.reshape({batch, kUpscaledChannels, h * w})).view({batch, kMaskTokens, h, w});
  masks.iou = iou_head_(out_tokens.select(1, 0));
  return masks;
}

}  // namespace matlearn
