#include "builtin/procedural_textures.h"

#include <utility>
#include <vector>

#include "matbase/image/unorm.h"
#include "matmaterial/library/height_normals.h"

namespace matgeom::builtin {

matbase::ImagePixels rgb_image(std::string name, int size, const std::function<glm::dvec3(double, double)>& texel) {
  matbase::ImagePixels image = matbase::blank_image(std::move(name), size, size, 3);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 rgb = texel((x + 0.5) / size, 1.0 - (y + 0.5) / size);
      for (int c = 0; c < 3; ++c) image.data[3 * (static_cast<size_t>(y) * size + x) + c] = matbase::unorm8(rgb[c]);
    }
  return image;
}

matbase::ImagePixels normal_map_image(std::string name, int size, const std::function<double(double, double)>& height,
                                      double texel_size) {
  std::vector<double> heights;
  heights.reserve(static_cast<size_t>(size) * static_cast<size_t>(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) heights.push_back(height((x + 0.5) / size, 1.0 - (y + 0.5) / size));
  matbase::ImagePixels image = matbase::blank_image(std::move(name), size, size, 3);
  for (int y = 0; y < size; ++y)
    matmaterial::library::normal_map_row(heights, size, texel_size, y, &image.data[static_cast<size_t>(3 * y * size)]);
  return image;
}

}  // namespace matgeom::builtin
