#pragma once
// A denoiser for the rendered colour, guided by the AOVs the renderer computes anyway: the
// edge-avoiding a-trous wavelet filter of Dammertz et al. 2010 ("Edge-Avoiding A-Trous Wavelet
// Transform for fast Global Illumination Filtering"), weighted as SVGF does it (Schied et al.
// 2017, "Spatiotemporal Variance-Guided Filtering", section 4.4, equations 1-5) on the colour
// divided by the base colour (its "irradiance", section 4.2), which keeps textures sharp. Pixels
// of different material labels are never mixed, so material boundaries stay where they are;
// background pixels (no hit) are left as they are. Deterministic: the same frame gives the same
// result on any thread count. Never part of Cycles parity (Blender 3.4 in Debian has no denoiser).
#include <cstdint>

#include "matrender/denoiser.h"
#include "matrender/frame.h"

namespace matrender {

struct AtrousFilterSettings {
  int iterations = 5;            // filter passes, the k-th with taps 2^k pixels apart (SVGF: 5)
  float sigma_luminance = 4.0f;  // SVGF's sigma_l: how many standard errors apart two pixels may be
  float sigma_normal = 128.0f;   // SVGF's sigma_n: the exponent on the normals' cosine
  float sigma_depth = 1.0f;      // SVGF's sigma_z: depth steps against the local depth gradient
  int threads = 0;               // 0 = all hardware threads; the result does not depend on it
};

// The AOVs atrous_filter() reads.
constexpr uint32_t kAtrousFilterGuideAovs = AovAlpha | AovColorVariance | AovNormalWorld | AovDepth | AovLabel |
                                            parameter_aov(MaterialParameter::BaseColor);

// Filters frame.color in place. Throws std::invalid_argument when a guide AOV is missing or the
// settings are out of range.
void atrous_filter(FrameBuffers& frame, const AtrousFilterSettings& settings = {});

// The filter as render() runs it for Denoising::Filter: with the default settings and the
// render's threads.
class AtrousFilter final : public Denoiser {
 public:
  uint32_t guide_aovs() const override { return kAtrousFilterGuideAovs; }
  void denoise(FrameBuffers& frame, int threads) const override;
};

}  // namespace matrender
