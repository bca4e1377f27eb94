#include "film/denoised_error.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace matrender {
namespace {

// A denoised frame's error falls as n^-kDenoisedErrorExponent from n / 2 samples to n (the header
// says why).
constexpr double kDenoisedErrorExponent = 1.0 / 3.0;

// The summed colour of a pixel's first (0) or second (1) half of samples.
glm::dvec3 half_colour(const PixelSums& whole, int half) {
  return half == 0 ? whole.first_half : whole.color - whole.first_half;
}

// One half of a pixel's samples as sums of their own: its colour, coverage and luminance
// squares (the a-trous filter's variance guide). The surface sums, which the albedo and normal
// guides come from, stay the whole's: they carry little noise.
PixelSums half_of(const PixelSums& whole, int half) {
  PixelSums part = whole;
  part.samples = whole.samples / 2;
  part.color = half_colour(whole, half);
  part.coverage = 0.5 * whole.coverage;
  part.luminance_squares = half == 0 ? whole.first_half_luminance_squares
                                     : whole.luminance_squares - whole.first_half_luminance_squares;
  return part;
}

// The mean colour of a pixel's half.
glm::dvec3 half_mean(const PixelSums& whole, int half) {
  return half_colour(whole, half) / (static_cast<double>(whole.samples) / 2.0);
}

// The film's unresolved surface sums that resolve() divides in place, for the AOVs of `aovs`.
void copy_surface_sums(const FrameBuffers& from, uint32_t aovs, FrameBuffers& to) {
  for (const matmaterial::MaterialParameterInfo& info : matmaterial::kMaterialParameters)
    if (aovs & parameter_aov(info.id)) to.parameter(info.id) = from.parameter(info.id);
  if (aovs & AovNormalTangent) to.normal_tangent = from.normal_tangent;
}

// Half `half` of every pixel resolved into a frame of the denoiser's guides, denoised: its colour.
std::vector<float> denoised_half(const std::vector<PixelSums>& sums, int half, const FrameBuffers& accumulating,
                                 const Denoiser& denoiser, const glm::mat3& world_to_camera, int threads) {
  const uint32_t guides = denoiser.guide_aovs();
  FrameBuffers probe;
  Film film(probe, accumulating.width, accumulating.height, guides, accumulating.transparent_background,
            world_to_camera);
  copy_surface_sums(accumulating, guides, probe);
  OcclusionFigures unused;
  for (size_t i = 0; i < sums.size(); ++i) film.resolve(i, half_of(sums[i], half), unused);
  denoiser.denoise(probe, threads);
  return std::move(probe.color);
}

}  // namespace

FrameErrorEstimate predict_denoised_error(const std::vector<PixelSums>& sums, const FrameErrorEstimate& undenoised,
                                          const FrameBuffers& accumulating, const Denoiser& denoiser,
                                          const glm::mat3& world_to_camera, int threads) {
  FrameErrorEstimate estimate = undenoised;
  if (estimate.pixels == 0) return estimate;
  const std::array<std::vector<float>, 2> denoised = {
      denoised_half(sums, 0, accumulating, denoiser, world_to_camera, threads),
      denoised_half(sums, 1, accumulating, denoiser, world_to_camera, threads)};
  // Each denoised half against the other half as sampled, less that half's own noise.
  double squared = 0.0;
  for (size_t i = 0; i < sums.size(); ++i) {
    if (!counts_in_frame_error(sums[i])) continue;
    const std::array<glm::dvec3, 2> raw = {half_mean(sums[i], 0), half_mean(sums[i], 1)};
    const glm::dvec3 half_variance = 0.5 * (raw[0] - raw[1]) * (raw[0] - raw[1]);
    for (int c = 0; c < 3; ++c) {
      const double a = static_cast<double>(denoised[0][3 * i + c]) - raw[1][c];
      const double b = static_cast<double>(denoised[1][3 * i + c]) - raw[0][c];
      squared += (0.5 * (a * a + b * b) - half_variance[c]) / 3.0;
    }
  }
  const double half_samples_mse = std::max(0.0, squared / static_cast<double>(estimate.pixels));
  estimate.mean_squared_error = half_samples_mse * std::pow(0.5, 2.0 * kDenoisedErrorExponent);
  estimate.relative_rmse = estimate.mean > 0.0 ? std::sqrt(estimate.mean_squared_error) / estimate.mean : 0.0;
  return estimate;
}

double denoised_error_bytes_per_pixel(const Denoiser& denoiser) {
  // One probe frame at a time, and the two denoised colours.
  return FrameBuffers::bytes_for(1, 1, denoiser.guide_aovs()) + 2.0 * 3.0 * sizeof(float);
}

}  // namespace matrender
