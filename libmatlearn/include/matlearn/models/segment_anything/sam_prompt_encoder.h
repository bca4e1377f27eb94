#pragma once
// Segment Anything's prompt encoder (Kirillov et al. 2023, "Segment Anything", section 3): points
// and box corners become 256-channel tokens (a random Fourier encoding of their position plus a
// learned embedding of their kind), and the image grid a dense positional encoding. Laid out as
// the official module "prompt_encoder" (6,220 parameters and its Gaussian matrix), so a converted
// checkpoint loads unchanged; the mask input's convolutions are there for the weights, unused.
#include <cstdint>
#include <optional>

#include <torch/torch.h>

namespace matlearn {

// Tancik et al. 2020's random Fourier features: a position c in [0, 1]^2 becomes
// [sin(2 pi (2c - 1) G), cos(2 pi (2c - 1) G)] for a fixed 2 x 128 Gaussian G (a trained buffer).
class SamPositionEncodingImpl : public torch::nn::Module {
 public:
  explicit SamPositionEncodingImpl(int64_t features = 128);
  // Positions ... x 2 (x, y) in [0, 1] to ... x 2 features.
  torch::Tensor encode(const torch::Tensor& positions) const;
  // The encoding of every cell centre of a side x side grid: 2 features x side x side.
  torch::Tensor grid(int64_t side) const;

 private:
  torch::Tensor gaussian_;
};
TORCH_MODULE(SamPositionEncoding);

// What a prompt may hold: points (B x N x 2 pixel coordinates in the 1024-pixel input frame,
// x then y, with B x N labels: 1 on the object, 0 off it) and a box (B x 4: x0, y0, x1, y1).
struct SamPromptTokens {
  torch::Tensor sparse;  // B x tokens x 256
  torch::Tensor dense;   // B x 256 x 64 x 64
};

class SamPromptEncoderImpl : public torch::nn::Module {
 public:
  static constexpr int64_t kEmbedDim = 256;
  static constexpr int64_t kInputSide = 1024;     // the image encoder's input
  static constexpr int64_t kEmbeddingSide = 64;   // its output grid
  SamPromptEncoderImpl();

  SamPromptTokens forward(const std::optional<torch::Tensor>& points, const std::optional<torch::Tensor>& labels,
                          const std::optional<torch::Tensor>& boxes);
  // The positional encoding of the image embedding's grid, 1 x 256 x 64 x 64.
  torch::Tensor dense_positional_encoding() const;

 private:
  torch::Tensor point_tokens(torch::Tensor points, torch::Tensor labels, bool padded) const;
  torch::Tensor box_tokens(const torch::Tensor& boxes) const;

  SamPositionEncoding position_{nullptr};
  torch::nn::ModuleList point_embeddings_{nullptr};  // negative point, positive point, box corner 0, box corner 1
  torch::nn::Embedding not_a_point_{nullptr}, no_mask_{nullptr};
  torch::nn::Sequential mask_downscaling_{nullptr};
};
TORCH_MODULE(SamPromptEncoder);

}  // namespace matlearn
