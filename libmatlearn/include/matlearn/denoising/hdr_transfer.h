#pragma once
// How the learned denoiser sees a high-dynamic-range colour (Afra et al.'s HDR input: an
// auto-exposure, then a transfer function, so the network works on a perceptually even range
// whatever the scene's brightness; the curve is ours). A pixel's linear value v in a frame of
// exposure e maps to
//
//   t(v) = ln(1 + e v / kTransferToe) / ln(1 + kTransferMax / kTransferToe)          (1)
//
// a logarithm, so that equal ratios of radiance are equal steps as the eye sees them, with a
// linear toe below kTransferToe, so that the noise around black is not stretched without bound,
// scaled so that kTransferMax, the largest half float, maps to 1. The exposure (Reinhard et al.
// 2002, "Photographic Tone Reproduction for Digital Images", equation 1, as OIDN uses it) puts
// the frame's log-average luminance at the key 0.18:
//
//   e = 0.18 / exp(mean over blocks of ln L_block)                                    (2)
//
// over the Rec.709 luminance of the frame's 16 x 16 pixel blocks, leaving out blocks darker
// than kDarkBlock (the empty background of an object alone); 1 when every block is.
#include <cstddef>

#include <torch/torch.h>

namespace matlearn {

constexpr float kTransferToe = 1.0f / 256.0f;
constexpr float kTransferMax = 65504.0f;
constexpr float kExposureKey = 0.18f;
constexpr int kExposureBlock = 16;
constexpr float kDarkBlock = 1e-8f;

// Equation 1 on exposed values (e v), NaN and values below 0 taken as 0 and above kTransferMax
// as it; and its inverse on [0, 1] (values outside taken as the nearest end).
torch::Tensor hdr_transfer(const torch::Tensor& exposed);
torch::Tensor hdr_transfer_inverse(const torch::Tensor& transferred);

// Equation 2 for an RGB image (width x height x 3, interleaved, linear); non-finite and negative
// values count as 0.
float auto_exposure(const float* rgb, int width, int height);

}  // namespace matlearn
