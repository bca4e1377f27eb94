#include "matrender/rig_lights.h"

namespace matrender {

Light rig_light(const matgeom::RigLight& light) {
  if (light.kind == matgeom::RigLightKind::Area)
    return RectLight{light.light_to_world, light.size_x, light.size_y, light.power, light.color};
  SpotLight spot;
  spot.position = light.position;
  spot.direction = -glm::dvec3(light.light_to_world[2]);
  spot.spot_angle = light.spot_angle;
  spot.blend = light.spot_blend;
  spot.power = light.power;
  spot.color = light.color;
  return spot;
}

std::vector<Light> rig_lights(const matgeom::LightRig& rig) {
  std::vector<Light> lights;
  for (const matgeom::RigLight& light : rig.lights) lights.push_back(rig_light(light));
  return lights;
}

}  // namespace matrender
