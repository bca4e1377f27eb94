#pragma once
// Procedural indoor objects that need no downloaded data.
#include <cstdint>
#include <string>
#include <vector>

#include "matgeom/object_asset.h"

namespace matgeom {

// Names accepted by make_builtin_object, in a stable order.
std::vector<std::string> builtin_object_names();

// Builds object `name` with shape parameters varied by `seed`; sizes in metres, resting on
// z = 0, outward normals, UVs, tangents and a built-in textured material per part.
// Throws std::invalid_argument for an unknown name.
ObjectAsset make_builtin_object(const std::string& name, uint32_t seed = 0);

}  // namespace matgeom
