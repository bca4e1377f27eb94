#include "matrender/frame.h"

#include <cstddef>

namespace matrender {

void FrameBuffers::resize(int w, int h, uint32_t aov_mask) {
  width = w;
  height = h;
  aovs = aov_mask;
  const std::size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  auto fit = [&](auto& buffer, Aov aov, std::size_t channels, auto fill) {
    buffer.assign((aov_mask & aov) ? n * channels : 0, fill);
  };
  color.assign(n * 3, 0.0f);
  fit(alpha, AovAlpha, 1, 0.0f);
  fit(base_color, AovBaseColor, 3, 0.0f);
  fit(roughness, AovRoughness, 1, 0.0f);
  fit(metallic, AovMetallic, 1, 0.0f);
  fit(normal_world, AovNormalWorld, 3, 0.0f);
  fit(normal_camera, AovNormalCamera, 3, 0.0f);
  fit(depth, AovDepth, 1, 0.0f);
  fit(label, AovLabel, 1, int32_t{0});
  fit(part_id, AovPartId, 1, int32_t{-1});
}

}  // namespace matrender
