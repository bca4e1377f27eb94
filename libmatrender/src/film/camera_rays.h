#pragma once
// Primary rays of the pinhole camera: raster (x + 0.5 + dx, y + 0.5 + dy), row 0 at the top,
// looking down camera -Z with +Y up (Blender's convention).
#include <cmath>
#include <optional>

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
        to_view_plane_(glm::inverse(glm::mat3(right_, up_, -back_))) {
    const double tan_half_fov = std::tan(0.5 * camera.vertical_fov);
    const double aspect = static_cast<double>(camera.width) / camera.height;
    scale_x_ = static_cast<float>(2.0 * tan_half_fov * aspect / camera.width);
    offset_x_ = static_cast<float>(tan_half_fov * aspect);
    scale_y_ = static_cast<float>(2.0 * tan_half_fov / camera.height);
    offset_y_ = static_cast<float>(tan_half_fov);
  }

  glm::vec3 origin() const { return origin_; }
  // The angle one pixel subtends at the image centre: a camera ray cone's spread (Akenine-Moller
  // et al. 2019, "Texture Level of Detail Strategies for Real-Time Ray Tracing", eq. 30).
  float pixel_spread_angle() const { return std::atan(scale_y_); }
  glm::vec3 forward() const { return -back_; }
  const glm::vec3& right() const { return right_; }
  const glm::vec3& up() const { return up_; }
  const glm::vec3& back() const { return back_; }

  // Unit direction through raster position (px, py) in pixels from the top-left corner: the
  // point (2 px / W - 1) tan(fov/2) aspect right, (1 - 2 py / H) tan(fov/2) up on the plane one
  // unit ahead, with the divisions folded into per-camera constants.
  glm::vec3 direction(float px, float py) const {
    const float sx = px * scale_x_ - offset_x_;
    const float sy = offset_y_ - py * scale_y_;
    return glm::normalize(sx * right_ + sy * up_ - back_);
  }

  // The raster position whose direction() points at world point p: p - origin written as
  // s (sx right + sy up - back) gives sx, sy, inverted as in direction(). Nothing when p is not
  // in front of the camera (s <= 0), where no camera ray points.
  std::optional<glm::vec2> raster_position(const glm::vec3& p) const {
    const glm::vec3 v = to_view_plane_ * (p - origin_);
    if (!(v.z > 0.0f)) return std::nullopt;
    const float sx = v.x / v.z, sy = v.y / v.z;
    return glm::vec2((sx + offset_x_) / scale_x_, (offset_y_ - sy) / scale_y_);
  }

 private:
  glm::vec3 origin_, right_, up_, back_;
  glm::mat3 to_view_plane_;  // from world offsets to (sx, sy, 1) times the distance along -back
  float scale_x_, offset_x_, scale_y_, offset_y_;
};

}  // namespace matrender
