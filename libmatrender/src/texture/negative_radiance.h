#pragma once
// Negative texels in an environment map: a radiance is never negative, but lossy EXR compression
// (DWAA, DWAB, B44) rings around edges and leaves small negative components behind. The eight
// HDRIs of Debian's blender-data reach -0.0016 to -0.0039 against means of 0.13 to 1.05, each at
// most 2.2 % of the largest component in its 3 x 3 neighbourhood. Cycles clamps them out of its
// importance map; a value no compression explains (-5 beside 0.5) is a broken file, refused.
#include <string>

#include "texture/texel_level.h"

namespace matrender {

// The depth of ringing a texel's neighbourhood explains: at most this fraction of the largest
// component in the 3 x 3 texels around it (u wraps, v stops at the poles), or of the image's mean
// in a dark area. Six times the deepest the blender-data HDRIs show.
constexpr float kRingingFraction = 1.0f / 8.0f;
constexpr float kDarkAreaFraction = 1.0f / 1024.0f;

// Sets to 0 every negative colour component of `level`'s float texels (alpha is not radiance) that
// ringing explains; throws std::runtime_error("<name>: texel (x, y) has ...") for the first that it
// does not. Rows are stored bottom first; messages count them from the top, as image tools do.
void clamp_compression_negatives(TexelLevel& level, const std::string& name);

}  // namespace matrender
