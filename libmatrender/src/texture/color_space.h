#pragma once
// sRGB transfer functions (IEC 61966-2-1).
#include <cmath>

namespace matrender {

inline float srgb_to_linear(float c) {
  if (c <= 0.04045f) return c < 0.0f ? 0.0f : c / 12.92f;
  return std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline float linear_to_srgb(float c) {
  if (c <= 0.0031308f) return c < 0.0f ? 0.0f : 12.92f * c;
  return 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

}  // namespace matrender
