#include "lights/rect_light_hits.h"

namespace matrender {

RectLightHits::RectLightHits(const std::vector<RectLight>& lamps) {
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
}

}  // namespace matrender
