#include "texture/negative_radiance.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace matrender {
namespace {

float largest_component(const glm::vec4& t) { return std::max({t.x, t.y, t.z}); }

}  // namespace

void clamp_compression_negatives(TexelLevel& level, const std::string& name) {
  if (level.floats.empty()) return;  // 8-bit texels cannot be negative
  const int width = level.width, height = level.height;
  double sum = 0.0;
  for (const glm::vec4& t : level.floats) sum += std::max(0.0, (static_cast<double>(t.x) + t.y + t.z) / 3.0);
  const float dark_floor = static_cast<float>(sum / static_cast<double>(level.floats.size())) * kDarkAreaFraction;
  // The largest component of each texel, read from before any clamping.
  std::vector<float> largest(level.floats.size());
  for (size_t i = 0; i < largest.size(); ++i) largest[i] = largest_component(level.floats[i]);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      glm::vec4& texel = level.floats[static_cast<size_t>(y) * width + x];
      if (!(texel.x < 0.0f || texel.y < 0.0f || texel.z < 0.0f)) continue;
      float neighbourhood = 0.0f;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int ny = std::clamp(y + dy, 0, height - 1), nx = ((x + dx) % width + width) % width;
          neighbourhood = std::max(neighbourhood, largest[static_cast<size_t>(ny) * width + nx]);
        }
      const float explained = std::max(neighbourhood * kRingingFraction, dark_floor);
      for (int c = 0; c < 3; ++c) {
        if (texel[c] >= 0.0f) continue;
        if (-texel[c] > explained)
          throw std::runtime_error(fmt::format(
              "{}: texel ({}, {}) has {} {:g}, a negative radiance no compression explains (the brightest texel "
              "around it is {:g}; ringing reaches at most {:g} of that): the file is damaged",
              name, x, height - 1 - y, "RGB"[c], texel[c], neighbourhood, kRingingFraction));
        texel[c] = 0.0f;
      }
    }
  }
}

}  // namespace matrender
