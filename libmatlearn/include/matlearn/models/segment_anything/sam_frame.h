#pragma once
// Between a photograph and Segment Anything's input: the image is resized so that its longer side
// is 1024 pixels (each side rounded to the nearest pixel: round(side * 1024 / longer)) and padded
// to 1024 x 1024 at the right and bottom; prompts follow it, and the masks come back through it.
#include <cstdint>

#include <torch/torch.h>

namespace matlearn {

struct SamFrame {
  static constexpr int64_t kInputSide = 1024;
  int64_t height = 0, width = 0;                  // the photograph's
  int64_t resized_height = 0, resized_width = 0;  // its part of the input

  static SamFrame of(int64_t height, int64_t width);
  // Pixel coordinates (x, y, ..., last dimension even) in the photograph to the input's.
  torch::Tensor to_input(const torch::Tensor& coordinates) const;
  // Mask logits B x K x h x w over the whole input (the decoder's 256 x 256) to the photograph's
  // size: bilinear to the input's side, the resized image's part cut out, bilinear to height x
  // width (both without aligning corners, as the official predictor). The object is where > 0.
  torch::Tensor logits_at_photo_size(const torch::Tensor& logits) const;
};

}  // namespace matlearn
