#pragma once
// Tileable procedural images for the built-in materials: the library's periodic noise and helpers
// that turn colour, roughness and height functions of (u, v) in [0, 1)^2 into 8-bit images.
#include <cstdint>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "matgeom/object_asset.h"
#include "matmaterial/library/periodic_noise.h"

namespace matgeom::builtin {

using matmaterial::library::hash32;
using matmaterial::library::hash_to_unit;

// The built-in objects' noise: the library's fractal value noise (matmaterial/library/
// periodic_noise.h), four octaves, blended as the vase's glaze was first drawn.
inline double fractal_noise(double u, double v, int base_period, uint32_t salt) {
  return matmaterial::library::fractal_noise({u, v}, glm::ivec2(base_period), 4, salt,
                                             matmaterial::library::ValueNoiseBlend::CubicOnceHashed);
}

// A size x size RGB image; texel(u, v) returns values in [0, 1] (sRGB-encoded for colour maps);
// rows run top to bottom, so row y holds v = 1 - (y + 0.5) / size.
matbase::ImagePixels rgb_image(std::string name, int size, const std::function<glm::dvec3(double, double)>& texel);

// Tangent-space normal map (matmaterial/library/height_normals.h) of the periodic height field
// height(u, v), sampled at texel centres, neighbouring texels `texel_size` apart in its unit.
matbase::ImagePixels normal_map_image(std::string name, int size, const std::function<double(double, double)>& height,
                                      double texel_size);

}  // namespace matgeom::builtin
