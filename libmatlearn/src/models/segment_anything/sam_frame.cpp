#include "matlearn/models/segment_anything/sam_frame.h"

#include <algorithm>
#include <stdexcept>

namespace matlearn {
namespace {

namespace F = torch::nn::functional;

torch::Tensor bilinear(const torch::Tensor& x, int64_t height, int64_t width) {
  return F::interpolate(x, F::InterpolateFuncOptions()
                               .size(std::vector<int64_t>{height, width})
                               .mode(torch::kBilinear)
                               .align_corners(false));
}

}  // namespace

SamFrame SamFrame::of(int64_t height, int64_t width) {
  if (height < 1 || width < 1) throw std::invalid_argument("SamFrame: an empty image");
  const double scale = static_cast<double>(kInputSide) / static_cast<double>(std::max(height, width));
  SamFrame frame;
  frame.height = height;
  frame.width = width;
  frame.resized_height = static_cast<int64_t>(static_cast<double>(height) * scale + 0.5);
  frame.resized_width = static_cast<int64_t>(static_cast<double>(width) * scale + 0.5);
  return frame;
}

torch::Tensor SamFrame::to_input(const torch::Tensor& coordinates) const {
  const torch::Tensor scale = torch::tensor({static_cast<double>(resized_width) / static_cast<double>(width),
                                             static_cast<double>(resized_height) / static_cast<double>(height)},
                                            torch::kFloat64);
  const auto shape = coordinates.sizes().vec();
  const torch::Tensor pairs = coordinates.to(torch::kFloat64).reshape({-1, 2}) * scale;
  return pairs.reshape(shape).to(torch::kFloat32);
}

torch::Tensor SamFrame::logits_at_photo_size(const torch::Tensor& logits) const {
  const torch::Tensor input = bilinear(logits, kInputSide, kInputSide);
  const torch::Tensor resized = input.narrow(2, 0, resized_height).narrow(3, 0, resized_width);
  return bilinear(resized, height, width);
}

}  // namespace matlearn
