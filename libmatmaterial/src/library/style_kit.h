#pragma once
// Small helpers the styles share: palettes picked in sRGB, soft steps, woven and perforated
// patterns. Everything periodic over the tile when its counts are whole.
#include <cmath>
#include <initializer_list>

#include <glm/glm.hpp>

#include "matbase/image/srgb.h"
#include "matbase/pi.h"
#include "matbase/smoothstep.h"
#include "matbase/uniform_source.h"

namespace matmaterial::library {

using matbase::kPi;

// The linear reflectance of an sRGB-encoded colour: palettes are picked by eye in sRGB.
inline glm::dvec3 from_srgb(double r, double g, double b) {
  return {matbase::srgb_to_linear(r), matbase::srgb_to_linear(g), matbase::srgb_to_linear(b)};
}

// One of the palette's (linear) colours, scaled by a factor within 1 +- jitter.
inline glm::dvec3 pick_colour(matbase::UniformSource& random, std::initializer_list<glm::dvec3> palette, double jitter) {
  const glm::dvec3 colour = palette.begin()[random.choice(static_cast<uint32_t>(palette.size()))];
  return colour * random.between(1.0 - jitter, 1.0 + jitter);
}

inline double fract(double x) { return x - std::floor(x); }

using matbase::smoothstep;

// A round thread's height across its width: 1 on its axis, 0 at its edges (t in [0, 1)).
inline double thread_profile(double t) { return std::sqrt(std::max(0.0, 1.0 - (2.0 * t - 1.0) * (2.0 * t - 1.0))); }

// Round holes of `radius` pitches on a count x count grid: 0 in a hole, 1 on the sheet, with a
// soft edge `edge` pitches wide.
inline double perforation_opacity(glm::dvec2 uv, int count, double radius, double edge) {
  const glm::dvec2 cell(fract(uv.x * count) - 0.5, fract(uv.y * count) - 0.5);
  return smoothstep(radius - 0.5 * edge, radius + 0.5 * edge, glm::length(cell));
}

}  // namespace matmaterial::library
