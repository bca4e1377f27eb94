#include "lights/rect_lights.h"

#include "lights/light_importance.h"

namespace matrender {

RectLights::RectLights(const std::vector<RectLight>& lamps) {
  Block padding{};
  for (size_t i = 0; i < kBlock; ++i) padding.half_x[i] = padding.half_y[i] = padding.radius2[i] = -1.0f;
  blocks_.assign((lamps.size() + kBlock - 1) / kBlock, padding);
  for (size_t lamp = 0; lamp < lamps.size(); ++lamp) {
    Block& k = blocks_[lamp / kBlock];
    const size_t i = lamp % kBlock;
    const Rectangle3& r = lamps[lamp].rectangle();
    const glm::vec3 c = lamps[lamp].center();
    k.center_x[i] = c.x, k.center_y[i] = c.y, k.center_z[i] = c.z;
    k.x_x[i] = r.x.x, k.x_y[i] = r.x.y, k.x_z[i] = r.x.z;
    k.y_x[i] = r.y.x, k.y_y[i] = r.y.y, k.y_z[i] = r.y.z;
    k.z_x[i] = r.z.x, k.z_y[i] = r.z.y, k.z_z[i] = r.z.z;
    k.half_x[i] = 0.5f * r.length_x;
    k.half_y[i] = 0.5f * r.length_y;
    // The half diagonal, 1 % larger.
    k.radius2[i] = 1.0201f * (k.half_x[i] * k.half_x[i] + k.half_y[i] * k.half_y[i]);
  }
  for (const RectLight& lamp : lamps) {
    const glm::vec3 c = lamp.center(), back = lamp.rectangle().z;
    center_x_.push_back(c.x), center_y_.push_back(c.y), center_z_.push_back(c.z);
    back_x_.push_back(back.x), back_y_.push_back(back.y), back_z_.push_back(back.z);
    radius_.push_back(lamp.bounding_radius());
    power_.push_back(lamp.power());
  }
}

void RectLights::importance(const glm::vec3& p, const ReceivingDirections& receiving, float* weights) const {
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
