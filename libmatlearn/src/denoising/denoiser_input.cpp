#include "matlearn/denoising/denoiser_input.h"

#include <cmath>
#include <stdexcept>

#include "matlearn/denoising/denoising_unet.h"
#include "matlearn/denoising/hdr_transfer.h"

namespace matlearn {
namespace {

// width x height x 3 interleaved -> 3 x height x width, non-finite values as 0.
torch::Tensor planar(const float* values, int width, int height) {
  const torch::Tensor interleaved =
      torch::from_blob(const_cast<float*>(values), {height, width, 3}, torch::kFloat32);
  return torch::nan_to_num(interleaved.permute({2, 0, 1}), 0.0, 0.0, 0.0).contiguous();
}

}  // namespace

torch::Tensor denoiser_input(const DenoiserFrame& frame, float exposure) {
  if (frame.width < 1 || frame.height < 1 || !frame.color || !frame.albedo || !frame.normal)
    throw std::invalid_argument("denoiser input: a frame needs a size, a colour, an albedo and a normal");
  if (!(std::isfinite(exposure) && exposure > 0.0f))
    throw std::invalid_argument("denoiser input: the exposure must be a positive number");
  const torch::Tensor coverage =
      frame.coverage ? torch::nan_to_num(torch::from_blob(const_cast<float*>(frame.coverage), {1, frame.height, frame.width},
                                                          torch::kFloat32),
                                         0.0, 0.0, 0.0)
                           .clamp(0.0, 1.0)
                     : torch::ones({1, frame.height, frame.width});
  const torch::Tensor color = hdr_transfer(planar(frame.color, frame.width, frame.height) * exposure);
  const torch::Tensor albedo = planar(frame.albedo, frame.width, frame.height).clamp(0.0, 1.0) * coverage;
  const torch::Tensor normal = planar(frame.normal, frame.width, frame.height).clamp(-1.0, 1.0) * coverage;
  return torch::cat({color, albedo, normal}, 0).unsqueeze(0);
}

std::vector<float> denoiser_output_colour(const torch::Tensor& output, float exposure) {
  if (output.dim() != 4 || output.size(0) != 1 || output.size(1) != 3)
    throw std::invalid_argument("denoiser output: expected 1 x 3 x H x W");
  const torch::Tensor linear = (hdr_transfer_inverse(output[0].to(torch::kFloat32)) / exposure).permute({1, 2, 0}).contiguous();
  const float* values = linear.data_ptr<float>();
  std::vector<float> colour(values, values + linear.numel());
  for (float& v : colour)
    if (!(std::isfinite(v) && v >= 0.0f)) v = 0.0f;
  return colour;
}

torch::Tensor pad_for_denoiser(const torch::Tensor& input) {
  const int64_t height = input.size(2), width = input.size(3);
  const int64_t bottom = (kDenoiserSideMultiple - height % kDenoiserSideMultiple) % kDenoiserSideMultiple;
  const int64_t right = (kDenoiserSideMultiple - width % kDenoiserSideMultiple) % kDenoiserSideMultiple;
  if (bottom == 0 && right == 0) return input;
  // The last row repeated below, then the last column to the right.
  torch::Tensor padded = torch::cat({input, input.narrow(2, height - 1, 1).expand({-1, -1, bottom, -1})}, 2);
  return torch::cat({padded, padded.narrow(3, width - 1, 1).expand({-1, -1, -1, right})}, 3);
}

}  // namespace matlearn
