#pragma once
// What a style of the procedural library computes: the maps as functions of the tile's (u, v)
// and the material's constants. The raster (library/recipe_raster.h) turns a recipe into a
// material folder's maps; the styles (library/*_styles.cpp) write recipes.
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "matmaterial/material_parameters.h"

namespace matmaterial::library {

// The maps' values at one point of the tile.
struct Texel {
  glm::dvec3 base_color{0.5};  // linear reflectance (the writer encodes it in sRGB)
  double roughness = 0.5;
  double metallic = 0.0;
  double height_m = 0.0;  // relief, metres: the normal map is its slope
  double opacity = 1.0;
};

struct Recipe {
  // Periodic over the unit square ((u, v) in [0, 1)^2, v up) and pure: it is called from
  // several threads.
  std::function<Texel(glm::dvec2 uv)> texel;
  // Parameters the maps do not hold (clearcoat, IOR, transmission, sheen, ...); the others keep
  // the table's defaults.
  std::vector<std::pair<MaterialParameter, glm::dvec3>> constants;
};

}  // namespace matmaterial::library
