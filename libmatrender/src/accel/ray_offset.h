#pragma once
// Spawning rays without self-intersection: Waechter and Binder 2019, "A Fast and Robust Method
// for Avoiding Self-Intersection" (Ray Tracing Gems, chapter 6). The origin moves along the
// geometric normal by a fixed number of float ULPs, so the offset scales with the magnitude of
// the hit position (1 cm and 10 m objects alike), with a small absolute step near the origin.
#include <cmath>
#include <cstdint>
#include <cstring>

#include <glm/glm.hpp>

namespace matrender {

inline float offset_float_ulps(float value, int32_t ulps) {
  int32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  bits += value < 0.0f ? -ulps : ulps;  // bits grow away from zero on both signs
  float result;
  std::memcpy(&result, &bits, sizeof result);
  return result;
}

// Moves p off the surface to the side n points to (n: unit geometric normal on that side).
inline glm::vec3 offset_ray_origin(const glm::vec3& p, const glm::vec3& n) {
  constexpr float kOriginRange = 1.0f / 32.0f;  // below this |coordinate| use an absolute step
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;
  glm::vec3 result;
  for (int i = 0; i < 3; ++i) {
    const int32_t ulps = static_cast<int32_t>(kIntScale * n[i]);
    // Adding ulps to the bit pattern moves a positive float up and a negative one down; the
    // sign flip makes the move follow n in both cases.
    result[i] = std::abs(p[i]) < kOriginRange ? p[i] + kFloatScale * n[i] : offset_float_ulps(p[i], ulps);
  }
  return result;
}

}  // namespace matrender
