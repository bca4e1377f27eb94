#pragma once
// What the learned denoiser reads of a frame, how it becomes the network's nine input channels
// (denoising_unet.h), and how the network's output becomes a colour again. One conversion for
// inference (a render's FrameBuffers) and training (pairs of a dataset's maps), so the network is
// trained on exactly what it is given.
#include <vector>

#include <torch/torch.h>

namespace matlearn {

// Interleaved arrays of width x height pixels, row 0 at the top.
struct DenoiserFrame {
  int width = 0;
  int height = 0;
  const float* color = nullptr;     // RGB, scene-linear (premultiplied by coverage over a transparent background)
  const float* albedo = nullptr;    // RGB base colour: the mean over the samples that hit, not premultiplied
  const float* normal = nullptr;    // XYZ world-space shading normal, the mean over the hits
  const float* coverage = nullptr;  // the fraction of the samples that hit; nullptr: 1 everywhere
};

// 1 x 9 x height x width: the colour through the transfer function at `exposure` (hdr_transfer.h,
// equation 1), the albedo clamped to [0, 1] and the normal clamped to [-1, 1], both times the
// coverage so that they fade at a silhouette as the colour does. Non-finite values read as 0.
torch::Tensor denoiser_input(const DenoiserFrame& frame, float exposure);

// The network's output (1 x 3 x H x W in the transfer function's range) as linear RGB,
// interleaved: the inverse transfer of the output clamped to [0, 1], over the exposure. Always
// finite and >= 0.
std::vector<float> denoiser_output_colour(const torch::Tensor& output, float exposure);

// Pads N x C x H x W on the right and bottom, repeating the last row and column, to sides that
// are multiples of kDenoiserSideMultiple.
torch::Tensor pad_for_denoiser(const torch::Tensor& input);

}  // namespace matlearn
