#include "matlearn/models/segment_anything/sam_prompt_encoder.h"

#include <cmath>

#include "matlearn/models/segment_anything/layer_norm_2d.h"

namespace matlearn {
namespace {

namespace nn = torch::nn;

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

}  // namespace

SamPositionEncodingImpl::SamPositionEncodingImpl(int64_t features) {
  gaussian_ = register_buffer("positional_encoding_gaussian_matrix", torch::randn({2, features}));
}

torch::Tensor SamPositionEncodingImpl::encode(const torch::Tensor& positions) const {
  const torch::Tensor phase = kTwoPi * torch::matmul(2.0 * positions - 1.0, gaussian_);
  return torch::cat({torch::sin(phase), torch::cos(phase)}, -1);
}

torch::Tensor SamPositionEncodingImpl::grid(int64_t side) const {
  const torch::Tensor centres = (torch::arange(side, gaussian_.options()) + 0.5) / static_cast<double>(side);
  const torch::Tensor y = centres.view({side, 1}).expand({side, side});
  const torch::Tensor x = centres.view({1, side}).expand({side, side});
  return encode(torch::stack({x, y}, -1)).permute({2, 0, 1});
}

SamPromptEncoderImpl::SamPromptEncoderImpl() {
  position_ = register_module("pe_layer", SamPositionEncoding(kEmbedDim / 2));
  point_embeddings_ = register_module("point_embeddings", nn::ModuleList());
  for (int k = 0; k < 4; ++k) point_embeddings_->push_back(nn::Embedding(1, kEmbedDim));
  not_a_point_ = register_module("not_a_point_embed", nn::Embedding(1, kEmbedDim));
  // Kept for the checkpoint's weights (a previous mask as a prompt), which isolation never gives.
  mask_downscaling_ = register_module(
      "mask_downscaling",
      nn::Sequential(nn::Conv2d(nn::Conv2dOptions(1, 4, 2).stride(2)), LayerNorm2d(4), nn::GELU(),
                     nn::Conv2d(nn::Conv2dOptions(4, 16, 2).stride(2)), LayerNorm2d(16), nn::GELU(),
                     nn::Conv2d(nn::Conv2dOptions(16, kEmbedDim, 1))));
  no_mask_ = register_module("no_mask_embed", nn::Embedding(1, kEmbedDim));
}

torch::Tensor SamPromptEncoderImpl::dense_positional_encoding() const {
  return position_->grid(kEmbeddingSide).unsqueeze(0);
}

// Points shift to their pixel's centre and scale to [0, 1]; without a box a point labelled -1
// pads the prompt, whose token is "not a point".
torch::Tensor SamPromptEncoderImpl::point_tokens(torch::Tensor points, torch::Tensor labels, bool padded) const {
  points = points + 0.5;
  if (padded) {
    points = torch::cat({points, torch::zeros({points.size(0), 1, 2}, points.options())}, 1);
    labels = torch::cat({labels, -torch::ones({labels.size(0), 1}, labels.options())}, 1);
  }
  torch::Tensor tokens = position_->encode(points / static_cast<double>(kInputSide));
  const torch::Tensor label = labels.unsqueeze(-1);
  const auto embedding = [&](size_t k) { return point_embeddings_->at<nn::EmbeddingImpl>(k).weight; };
  tokens = torch::where(label == -1, torch::zeros_like(tokens) + not_a_point_->weight, tokens);
  tokens = tokens + torch::where(label == 0, embedding(0), torch::zeros_like(tokens));
  tokens = tokens + torch::where(label == 1, embedding(1), torch::zeros_like(tokens));
  return tokens;
}

torch::Tensor SamPromptEncoderImpl::box_tokens(const torch::Tensor& boxes) const {
  const torch::Tensor corners = (boxes + 0.5).view({-1, 2, 2}) / static_cast<double>(kInputSide);
  torch::Tensor tokens = position_->encode(corners);
  const torch::Tensor kinds = torch::cat({point_embeddings_->at<nn::EmbeddingImpl>(2).weight,
                                          point_embeddings_->at<nn::EmbeddingImpl>(3).weight});
  return tokens + kinds.unsqueeze(0);
}

SamPromptTokens SamPromptEncoderImpl::forward(const std::optional<torch::Tensor>& points,
                                              const std::optional<torch::Tensor>& labels,
                                              const std::optional<torch::Tensor>& boxes) {
  const int64_t batch = points ? points->size(0) : boxes ? boxes->size(0) : 1;
  torch::Tensor sparse = torch::empty({batch, 0, kEmbedDim}, no_mask_->weight.options());
  if (points) sparse = torch::cat({sparse, point_tokens(*points, *labels, !boxes)}, 1);
  if (boxes) sparse = torch::cat({sparse, box_tokens(*boxes)}, 1);
  const torch::Tensor dense =
      no_mask_->weight.view({1, kEmbedDim, 1, 1}).expand({batch, kEmbedDim, kEmbeddingSide, kEmbeddingSide});
  return {sparse, dense};
}

}  // namespace matlearn
