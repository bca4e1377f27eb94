#pragma once
// What a lamp must be for single-precision shading to render it as described: finite values,
// positions within the scene limit (matrender/scene_limits.h), a rectangle whose area and
// radiance, and a point lamp whose intensity, are finite non-zero floats.
#include <optional>
#include <string>

#include "matrender/light.h"

namespace matrender {

// Why the lamp cannot be rendered as given ("power 1e+308 W exceeds ..."), or nothing.
std::optional<std::string> light_problem(const Light& light);

}  // namespace matrender
