#pragma once
// Cycles' pixel filter: Blackman-Harris of the film's filter width w (Blender's Film > Pixel
// Filter > Width, 1.5 px by default), which Cycles doubles internally, so the window spans
// [-w, w] px. Offsets are importance-sampled separably through the
// inverted CDF and every sample has weight 1 (Cycles' filter_table; the pixel is the plain mean).
#include <algorithm>
#include <array>

#include <glm/glm.hpp>

namespace matrender {

// w(x) = 0.35875 - 0.48829 cos a + 0.14128 cos 2a - 0.01168 cos 3a, a = 2 pi (x / (2 r) + 0.5),
// for x in [-r, r] px (Blackman-Harris over the doubled width r), 0 outside.
double blackman_harris_weight(double x, double radius);

class PixelFilterSampler {
 public:
  // Blender's default width, 1.5 px.
  static constexpr double kDefaultRadius = 1.5;

  // The filter of width `radius` px (RenderSettings::filter_width).
  explicit PixelFilterSampler(double radius = kDefaultRadius);
  double radius() const { return radius_; }

  // Maps u in [0,1)^2 to an offset from the pixel centre, distributed as w(x) w(y).
  glm::vec2 sample(glm::vec2 u) const { return {inverse_cdf(u.x), inverse_cdf(u.y)}; }
  // The 1-D inverse CDF, interpolated linearly in the table.
  float inverse_cdf(float u) const {
    const float x = std::clamp(u, 0.0f, 1.0f) * kTableSize;
    const int i = std::min(static_cast<int>(x), kTableSize - 1);
    const float t = x - static_cast<float>(i);
    return inverse_cdf_[i] + t * (inverse_cdf_[i + 1] - inverse_cdf_[i]);
  }

 private:
  static constexpr int kTableSize = 1024;
  double radius_;
  std::array<float, kTableSize + 1> inverse_cdf_{};
};

// The filter of Blender's default width, made once.
const PixelFilterSampler& blackman_harris_sampler();

}  // namespace matrender
