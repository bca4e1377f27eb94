#pragma once
// Primary rays of the pinhole camera: raster (x + 0.5 + dx, y + 0.5 + dy), row 0 at the top,
// looking down camera -Z with +Y up (Blender's convention).
#include <cmath>

#include <glm/glm.hpp>

#include "matrender/camera.h"

namespace matrender {

class CameraRays {
 public:
  explicit CameraRays(const Camera& camera)
      : origin_(glm::vec3(camera.camera_to_world[3])),
        right_(glm::normalize(glm::vec3(camera.camera_to_world[0]))),
        up_(glm::normalize(glm::vec3(camera.camera_to_world[1]))),
        back_(glm::normalize(glm::vec3(camera.camera_to_world[2]))),
        tan_half_fov_(static_cast<float>(std::tan(0.5 * camera.vertical_fov))),
        width_(static_cast<float>(camera.width)),
        height_(static_cast<float>(camera.height)) {}

  glm::vec3 origin() const { return origin_; }
  glm::vec3 forward() const { return -back_; }
  const glm::vec3& right() const { return right_; }
  const glm::vec3& up() const { return up_; }
  const glm::vec3& back() const { return back_; }

  // Unit direction through raster position (px, py) in pixels from the top-left corner.
  glm::vec3 direction(float px, float py) const {
    const float sx = (2.0f * px / width_ - 1.0f) * tan_half_fov_ * (width_ / height_);
    const float sy = (1.0f - 2.0f * py / height_) * tan_half_fov_;
    return glm::normalize(sx * right_ + sy * up_ - back_);
  }

 private:
  glm::vec3 origin_, right_, up_, back_;
  float tan_half_fov_;
  float width_, height_;
};

}  // namespace matrender
