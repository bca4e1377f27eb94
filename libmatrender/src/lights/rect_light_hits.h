#pragma once
// The ray test every BSDF-sampled ray makes against every rectangular lamp, over the lamps'
// geometry stored as structure-of-arrays in blocks of kBlock so that the compiler evaluates a
// block with SIMD instructions and no branch per lamp.
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "lights/rect_light.h"

namespace matrender {

class RectLightHits {
 public:
  static constexpr size_t kBlock = 8;

  explicit RectLightHits(const std::vector<PreparedRectLight>& lamps);

  bool empty() const { return count_ == 0; }

  // Calls visit(lamp_index, t) for every lamp whose emitting side the ray meets at a distance
  // t in (0, t_max), in lamp order.
  template <class Visit>
  void for_each_hit(const glm::vec3& origin, const glm::vec3& dir, float t_max, Visit&& visit) const {
    for (size_t base = 0; base < count_; base += kBlock) {
      float t_hit[kBlock];
      for (size_t i = 0; i < kBlock; ++i) {
        const size_t k = base + i;
        // Plane through the centre with normal z (the lamp's back); it emits toward -z, so a
        // ray sees the emitting side when it travels along +z.
        const float facing = dir.x * z_x_[k] + dir.y * z_y_[k] + dir.z * z_z_[k];
        const float to_center_x = center_x_[k] - origin.x, to_center_y = center_y_[k] - origin.y,
                    to_center_z = center_z_[k] - origin.z;
        const float t = (to_center_x * z_x_[k] + to_center_y * z_y_[k] + to_center_z * z_z_[k]) / facing;
        const float px = t * dir.x - to_center_x, py = t * dir.y - to_center_y, pz = t * dir.z - to_center_z;
        const float lx = px * x_x_[k] + py * x_y_[k] + pz * x_z_[k];
        const float ly = px * y_x_[k] + py * y_y_[k] + pz * y_z_[k];
        // Non-short-circuit & keeps the loop free of branches, so it vectorises.
        const bool hit = (facing > 0.0f) & (t > 0.0f) & (t < t_max) & (std::abs(lx) <= half_x_[k]) &
                         (std::abs(ly) <= half_y_[k]);
        t_hit[i] = hit ? t : -1.0f;
      }
      for (size_t i = 0; i < kBlock; ++i)
        if (t_hit[i] > 0.0f) visit(base + i, t_hit[i]);
    }
  }

 private:
  size_t count_ = 0;
  // Padded to a multiple of kBlock with lamps of negative size, which no ray hits.
  std::vector<float> center_x_, center_y_, center_z_, x_x_, x_y_, x_z_, y_x_, y_y_, y_z_, z_x_, z_y_, z_z_,
      half_x_, half_y_;
};

}  // namespace matrender
