#pragma once
// The sRGB transfer function (IEC 61966-2-1), in float and double, for every library: 8-bit
// colour textures decode through it, display images encode through it. Negative values map to 0.
// And the luminance of a linear colour in sRGB's (Rec.709's) primaries.
#include <cmath>

namespace matbase {

inline float srgb_to_linear(float c) {
  if (c <= 0.04045f) return c < 0.0f ? 0.0f : c / 12.92f;
  return std::pow((c + 0.055f) / 1.055f, 2.4f);
}

inline double srgb_to_linear(double c) {
  if (c <= 0.04045) return c < 0.0 ? 0.0 : c / 12.92;
  return std::pow((c + 0.055) / 1.055, 2.4);
}

inline double linear_to_srgb(double c) {
  if (c <= 0.0031308) return c < 0.0 ? 0.0 : 12.92 * c;
  return 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

inline float linear_to_srgb(float c) {
  if (c <= 0.0031308f) return c < 0.0f ? 0.0f : 12.92f * c;
  return 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Luminance Y of a linear colour in the Rec.709 primaries sRGB shares (ITU-R BT.709, the Y row of
// its RGB-to-XYZ matrix), for glm's float and double vectors alike.
template <typename Vec3>
typename Vec3::value_type rec709_luminance(const Vec3& c) {
  using T = typename Vec3::value_type;
  return T(0.2126) * c.x + T(0.7152) * c.y + T(0.0722) * c.z;
}

}  // namespace matbase
