#include "lights/rect_light_hits.h"

namespace matrender {

RectLightHits::RectLightHits(const std::vector<PreparedRectLight>& lamps) : count_(lamps.size()) {
  const size_t padded = (count_ + kBlock - 1) / kBlock * kBlock;
  for (auto* array : {&center_x_, &center_y_, &center_z_, &x_x_, &x_y_, &x_z_, &y_x_, &y_y_, &y_z_, &z_x_, &z_y_,
                      &z_z_})
    array->assign(padded, 0.0f);
  half_x_.assign(padded, -1.0f);
  half_y_.assign(padded, -1.0f);
  for (size_t k = 0; k < count_; ++k) {
    const Rectangle3& r = lamps[k].rectangle();
    const glm::vec3 c = lamps[k].center();
    center_x_[k] = c.x, center_y_[k] = c.y, center_z_[k] = c.z;
    x_x_[k] = r.x.x, x_y_[k] = r.x.y, x_z_[k] = r.x.z;
    y_x_[k] = r.y.x, y_y_[k] = r.y.y, y_z_[k] = r.y.z;
    z_x_[k] = r.z.x, z_y_[k] = r.z.y, z_z_[k] = r.z.z;
    half_x_[k] = 0.5f * r.length_x;
    half_y_[k] = 0.5f * r.length_y;
  }
}

}  // namespace matrender
