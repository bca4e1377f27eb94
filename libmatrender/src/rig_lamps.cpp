#include "matrender/rig_lamps.h"

namespace matrender {

Lamp rig_lamp(const matgeom::RigLight& light) {
  if (light.kind == matgeom::RigLightKind::Area)
    return RectLamp{light.light_to_world, light.size_x, light.size_y, light.power, light.color};
  SpotLamp spot;
  spot.position = light.position;
  spot.direction = -glm::dvec3(light.light_to_world[2]);
  spot.spot_angle = light.spot_angle;
  spot.blend = light.spot_blend;
  spot.power = light.power;
  spot.color = light.color;
  return spot;
}

std::vector<Lamp> rig_lamps(const matgeom::LightRig& rig) {
  std::vector<Lamp> lights;
  for (const matgeom::RigLight& light : rig.lights) lights.push_back(rig_lamp(light));
  return lights;
}

}  // namespace matrender
