#pragma once
// Normalised integer codes (8-bit and 16-bit image values), one rounding rule for every library:
// a value in [0, 1] maps to the nearest code, values outside clamp, a value that is not finite
// is 0.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace matgeom {

// The code of v in [0, max_code] (255 for 8 bits, 65535 for 16).
inline uint16_t unorm_code(double v, uint16_t max_code) {
  if (!std::isfinite(v)) return 0;
  return static_cast<uint16_t>(std::clamp(std::lround(v * max_code), 0L, static_cast<long>(max_code)));
}

inline uint8_t unorm8(double v) { return static_cast<uint8_t>(unorm_code(v, 255)); }

// The nearest 8-bit code of a 16-bit one.
inline uint8_t unorm16_to_unorm8(uint16_t code) {
  return static_cast<uint8_t>((static_cast<uint32_t>(code) * 255u + 32767u) / 65535u);
}

}  // namespace matgeom
