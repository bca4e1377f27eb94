#include "matmaterial/library/height_normals.h"

#include <glm/glm.hpp>

#include "matbase/image/unorm.h"

namespace matmaterial::library {

void normal_map_row(const std::vector<double>& heights, int resolution, double texel_size, int y, uint8_t* rgb) {
  const auto at = [&](int x, int row) {
    const int wx = (x + resolution) % resolution, wy = (row + resolution) % resolution;
    return heights[static_cast<size_t>(wy) * static_cast<size_t>(resolution) + static_cast<size_t>(wx)];
  };
  const double two_texels = 2.0 * texel_size;
  for (int x = 0; x < resolution; ++x) {
    const double dh_du = (at(x + 1, y) - at(x - 1, y)) / two_texels;
    const double dh_dv = (at(x, y - 1) - at(x, y + 1)) / two_texels;  // rows run down the image, v up it
    const glm::dvec3 n = glm::normalize(glm::dvec3(-dh_du, -dh_dv, 1.0));
    for (int c = 0; c < 3; ++c) rgb[3 * x + c] = matbase::unorm8(0.5 * n[c] + 0.5);
  }
}

}  // namespace matmaterial::library
