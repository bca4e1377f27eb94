#pragma once
// Rendering to an error with a denoiser (RenderSettings::target_error and denoise; docs/
// conventions.md, "Rendering to an error"): the target is for the denoised frame. Its error is
// predicted, like the frame's (error_target.h), from each pixel's two halves A and B, each made
// into a frame of its own (its colour and variance; the albedo and normal guides from all
// samples) and denoised into D_A and D_B:
//
// - Each denoised half against the other half as sampled: E (D_A - B)^2 = e^2 + V, where e^2 is
//   the denoised half's squared error, its noise and its bias (a blurred texture) alike, and V
//   the other half's own noise, which (A - B)^2 / 2 estimates; their difference, averaged over
//   both pairings and the covered pixels, is e^2 at n / 2 samples. (The halves' disagreement
//   (D_A - D_B)^2 / 4 misses the bias, and a denoiser that smooths harder the noisier its input
//   is removes more of a half's noise than of the whole's: on the lamp-lit ball with the a-trous
//   filter it predicted 2.6 % where 3.9 % was measured. Monte-Carlo SURE on the whole, which
//   perturbs the colour but not the variance guide, predicted the same.)
// - From n / 2 samples to n the denoised error is taken to fall as n^(-1/3): between a denoiser
//   whose gain lasts (n^(-1/2), the undenoised rate) and one whose bias no sample removes. The
//   a-trous filter on that ball fell by 0.73 to 0.81 a doubling (2^(-1/3) = 0.79).
//
// Sampling then plans its rounds as without a denoiser, for the target scaled by how much the
// denoiser takes off this round (predicted undenoised error over predicted denoised error), and
// stops when the denoised prediction reaches the target.
#include <vector>

#include <glm/glm.hpp>

#include "film/error_target.h"
#include "film/film.h"
#include "matrender/denoiser.h"
#include "matrender/frame.h"

namespace matrender {

// The denoised frame's error predicted from the pixels' sums and the undenoised prediction
// (predict_frame_error, whose covered pixels and mean colour it shares). `accumulating` is the
// frame the film sums into (its material parameter and tangent-space normal sums, not yet
// resolved): the denoiser's guides come from every sample so far, the colour from one half at a
// time.
FrameErrorEstimate predict_denoised_error(const std::vector<PixelSums>& sums, const FrameErrorEstimate& undenoised,
                                          const FrameBuffers& accumulating, const Denoiser& denoiser,
                                          const glm::mat3& world_to_camera, int threads);

// The bytes predict_denoised_error needs beside the frame, per pixel.
double denoised_error_bytes_per_pixel(const Denoiser& denoiser);

}  // namespace matrender
