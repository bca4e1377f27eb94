#pragma once
// Normalised integer codes (8-bit and 16-bit image values), one rounding rule for every library:
// a value in [0, 1] maps to the nearest code, values outside clamp, a value that is not finite
// is 0.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace matbase {

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

// The 8-bit channels of decoded image bytes holding `bits` (8 or 16) per channel, 16-bit ones as
// native-endian codes (stb_image's layout), each rounded to the nearest 8-bit code.
inline std::vector<uint8_t> unorm_channels_to_8_bit(const std::vector<unsigned char>& bytes, int bits) {
  if (bits == 8) return std::vector<uint8_t>(bytes.begin(), bytes.end());
  std::vector<uint8_t> channels(bytes.size() / 2);
  for (size_t i = 0; i < channels.size(); ++i) {
    uint16_t code;
    std::memcpy(&code, bytes.data() + 2 * i, sizeof(code));
    channels[i] = unorm16_to_unorm8(code);
  }
  return channels;
}

}  // namespace matbase
