#include "lights/rect_lamp_importance.h"

#include "lights/light_importance.h"

namespace matrender {

RectLampImportance::RectLampImportance(const std::vector<RectLight>& lamps) {
  for (const RectLight& lamp : lamps) {
    const glm::vec3 c = lamp.center(), back = lamp.rectangle().z;
    center_x_.push_back(c.x), center_y_.push_back(c.y), center_z_.push_back(c.z);
    back_x_.push_back(back.x), back_y_.push_back(back.y), back_z_.push_back(back.z);
    radius_.push_back(lamp.bounding_radius());
    power_.push_back(lamp.power());
  }
}

void RectLampImportance::evaluate(const glm::vec3& p, const ReceivingDirections& receiving, float* weights) const {
  // The same function as RectLight::importance, lamp by lamp; the compiler runs the
  // iterations side by side once `every_direction` is a constant in the loop (a select on it
  // would keep the loop scalar).
  const auto each_lamp = [&](const ReceivingDirections& constant_receiving) {
    for (size_t i = 0; i < size(); ++i)
      weights[i] = one_sided_emitter_importance(glm::vec3(center_x_[i], center_y_[i], center_z_[i]),
                                                glm::vec3(back_x_[i], back_y_[i], back_z_[i]), radius_[i], power_[i],
                                                p, constant_receiving);
  };
  if (receiving.every_direction)
    each_lamp({receiving.normal, true});
  else
    each_lamp({receiving.normal, false});
}

}  // namespace matrender
