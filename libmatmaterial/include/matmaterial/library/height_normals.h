#pragma once
// The tangent-space normal map of a periodic height field, the one way every procedural map is
// given its normals: the library's materials and the built-in objects' textures.
#include <cstdint>
#include <vector>

namespace matmaterial::library {

// Row y of the normal map (3 bytes per texel, OpenGL's convention: +X along +u, +Y along +v) of
// `heights`, resolution x resolution texels in rows top to bottom that wrap at the edges, by
// central differences between the neighbours of each texel, `texel_size` apart in the heights'
// unit (metres for the library's maps).
void normal_map_row(const std::vector<double>& heights, int resolution, double texel_size, int y, uint8_t* rgb);

}  // namespace matmaterial::library
