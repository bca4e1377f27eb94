#include "film/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace matrender {

std::optional<AdaptiveSampling> AdaptiveSampling::from_settings(double noise_threshold, int min_samples) {
  if (!(noise_threshold > 0.0)) return std::nullopt;
  const float threshold = static_cast<float>(noise_threshold);
  const int automatic = static_cast<int>(std::ceil(16.0f / std::pow(threshold, 0.3f)));
  const int minimum = std::max(4, min_samples == 0 ? automatic : min_samples);
  return AdaptiveSampling(5.0f * threshold, static_cast<uint32_t>(minimum));
}

uint32_t AdaptiveSampling::next_check(uint32_t samples) const {
  // Cycles' first filtered sample index is (min_samples + 1) | (kStep - 1); counts are one more.
  const uint32_t first = ((min_samples_ + 1) | (kStep - 1)) + 1;
  if (samples < first) return first;
  return (samples / kStep + 1) * kStep;
}

bool pixel_converged(const glm::dvec3& sum, const glm::dvec3& second_estimate_sum, uint32_t samples,
                     float error_bound) {
  const double inv_samples = 1.0 / static_cast<double>(samples);
  const glm::dvec3 difference = glm::abs(sum - 2.0 * second_estimate_sum);
  const double error_difference = (difference.x + difference.y + difference.z) * inv_samples;
  // Negative sums (none from a path tracer, but a caller's) count as black, not as NaN.
  const double error_normalize = std::sqrt(std::max(0.0, (sum.x + sum.y + sum.z) * inv_samples));
  return error_difference / (1e-4 + error_normalize) < static_cast<double>(error_bound);
}

namespace {

// One pass of the box filter: a pixel stays converged only if its two neighbours `stride` away
// along the line (within the line's `count` pixels) are converged too.
void dilate_unconverged(std::vector<uint8_t>& converged, size_t start, size_t stride, size_t count) {
  bool previous_unconverged = false;
  for (size_t k = 0; k < count; ++k) {
    uint8_t& pixel = converged[start + k * stride];
    const bool unconverged = pixel == 0;
    if (!unconverged && (previous_unconverged || (k + 1 < count && converged[start + (k + 1) * stride] == 0)))
      pixel = 0;
    previous_unconverged = unconverged;
  }
}

}  // namespace

void keep_neighbours_sampling(std::vector<uint8_t>& converged, int width, int height) {
  const size_t w = static_cast<size_t>(width), h = static_cast<size_t>(height);
  for (size_t y = 0; y < h; ++y) dilate_unconverged(converged, y * w, 1, w);
  for (size_t x = 0; x < w; ++x) dilate_unconverged(converged, x, w, h);
}

}  // namespace matrender
