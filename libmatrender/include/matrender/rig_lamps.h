#pragma once
// The paper's light rig (matgeom/light_rig.h) as libmatrender lamps: its area lights become
// rectangle lamps, its accents for small objects spot lamps, both emitting down their local -Z.
#include <vector>

#include "matgeom/light_rig.h"
#include "matrender/lamp.h"

namespace matrender {

Lamp rig_lamp(const matgeom::RigLight& light);
std::vector<Lamp> rig_lamps(const matgeom::LightRig& rig);

}  // namespace matrender
