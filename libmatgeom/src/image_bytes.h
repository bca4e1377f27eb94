#pragma once
// The 8-bit channels of an image decoded through tinygltf (stb), as the glTF and OBJ readers keep
// their images.
#include <cstdint>
#include <cstring>
#include <vector>

#include <tiny_gltf.h>

#include "matgeom/unorm.h"

namespace matgeom {

// 16-bit channels round to the nearest 8-bit code.
inline std::vector<uint8_t> to_8_bit(const tinygltf::Image& image) {
  if (image.bits == 8) return std::vector<uint8_t>(image.image.begin(), image.image.end());
  std::vector<uint8_t> bytes(image.image.size() / 2);
  for (size_t i = 0; i < bytes.size(); ++i) {
    uint16_t value;
    std::memcpy(&value, image.image.data() + 2 * i, sizeof(value));
    bytes[i] = unorm16_to_unorm8(value);
  }
  return bytes;
}

}  // namespace matgeom
