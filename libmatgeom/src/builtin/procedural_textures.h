#pragma once
// Tileable procedural images for the built-in materials: periodic value noise and helpers that
// turn colour, roughness and height functions of (u, v) in [0, 1)^2 into 8-bit images.
#include <cstdint>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "matgeom/object_asset.h"
#include "matmaterial/library/periodic_noise.h"

namespace matgeom::builtin {

using matmaterial::library::hash32;
using matmaterial::library::hash_to_unit;

// Value noise in [0, 1) on a lattice of period_x x period_y cells across the unit square,
// periodic in both axes, smoothstep-interpolated.
double periodic_value_noise(double x, double y, int period_x, int period_y, uint32_t salt);
double periodic_value_noise(double x, double y, int period, uint32_t salt);

// Four octaves from `base_period` cells up, normalised back to [0, 1).
double fractal_noise(double x, double y, int base_period, uint32_t salt);
// The same with different cell counts along x and y: streaks when they differ.
double fractal_noise(double x, double y, int base_period_x, int base_period_y, uint32_t salt);


// A size x size RGB image; texel(u, v) returns values in [0, 1] (sRGB-encoded for colour maps);
// rows run top to bottom, so row y holds v = 1 - (y + 0.5) / size.
matbase::ImagePixels rgb_image(std::string name, int size, const std::function<glm::dvec3(double, double)>& texel);

// Tangent-space normal map (OpenGL convention, +Y = +v) of the periodic height field height(u, v)
// by central differences; `bump` scales the height difference per texel into slope.
matbase::ImagePixels normal_map_image(std::string name, int size, const std::function<double(double, double)>& height,
                             double bump);

}  // namespace matgeom::builtin
