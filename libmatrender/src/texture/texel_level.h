#pragma once
// One level of a texture's texels, as stored: RGBA floats, or RGBA bytes for 8-bit images whose
// colour is not premultiplied at load (a quarter of the memory: 64 MiB for a 4k map instead of
// 256). Rows bottom to top, so that v = 0 is row 0.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace matrender {

struct TexelLevel {
  int width = 0, height = 0;
  std::vector<glm::vec4> floats;  // one of the two is filled
  std::vector<uint8_t> bytes;

  bool stored_as_bytes() const { return !bytes.empty(); }
  size_t memory_bytes() const { return floats.size() * sizeof(glm::vec4) + bytes.size(); }
  glm::vec4 texel(int x, int y) const {
    const size_t i = static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x);
    if (bytes.empty()) return floats[i];
    const uint8_t* b = bytes.data() + 4 * i;
    return glm::vec4(b[0], b[1], b[2], b[3]) * (1.0f / 255.0f);
  }
};

// The next coarser mip level: sides halved (rounding up), each texel the mean of the 2 x 2
// texels below it, edge texels repeated on odd sides; stored as `finer` is (bytes round to the
// nearest byte).
TexelLevel box_filtered_half(const TexelLevel& finer);

// How many levels a pyramid of box_filtered_half steps down to 1 x 1 has, level 0 included.
size_t mip_level_count(int width, int height);

}  // namespace matrender
