#include "texture/texel_level.h"

#include <algorithm>
#include <cmath>

namespace matrender {

TexelLevel box_filtered_half(const TexelLevel& finer) {
  TexelLevel coarser;
  coarser.width = std::max(1, (finer.width + 1) / 2);
  coarser.height = std::max(1, (finer.height + 1) / 2);
  const size_t count = static_cast<size_t>(coarser.width) * static_cast<size_t>(coarser.height);
  const bool bytes = finer.stored_as_bytes();
  if (bytes) coarser.bytes.resize(4 * count); else coarser.floats.resize(count);
  const auto at = [&](int x, int y) { return finer.texel(std::min(x, finer.width - 1), std::min(y, finer.height - 1)); };
  for (int y = 0; y < coarser.height; ++y)
    for (int x = 0; x < coarser.width; ++x) {
      const glm::vec4 mean =
          0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
      const size_t i = static_cast<size_t>(y) * static_cast<size_t>(coarser.width) + static_cast<size_t>(x);
      if (!bytes) {
        coarser.floats[i] = mean;
        continue;
      }
      for (int c = 0; c < 4; ++c) coarser.bytes[4 * i + c] = static_cast<uint8_t>(std::lround(mean[c] * 255.0f));
    }
  return coarser;
}

size_t mip_level_count(int width, int height) {
  size_t levels = 1;
  while (width > 1 || height > 1) {
    width = std::max(1, (width + 1) / 2);
    height = std::max(1, (height + 1) / 2);
    ++levels;
  }
  return levels;
}

}  // namespace matrender
