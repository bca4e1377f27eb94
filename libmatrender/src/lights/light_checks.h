#pragma once
// What a lamp must be for single-precision shading to render it as described: finite values,
// positions within the scene limit (matrender/scene_limits.h), a rectangle whose area and
// radiance, and a point lamp whose intensity, are finite non-zero floats.
#include <cmath>
#include <optional>
#include <string>

#include "matbase/pi.h"
#include "matrender/light.h"

namespace matrender {

// The widest sun: Blender takes 180 degrees, where the disk of directions, of radius
// tan(angle / 2), becomes infinite; at 179 degrees it is 115 wide.
constexpr double kMaxSunAngle = 179.0 * matbase::kPi / 180.0;

// Why the lamp cannot be rendered as given ("power 1e+308 W exceeds ..."), or nothing.
std::optional<std::string> light_problem(const Light& light);

}  // namespace matrender
