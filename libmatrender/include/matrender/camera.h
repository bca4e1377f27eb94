#pragma once
// Pinhole camera in Blender's convention: looks down its local -Z, +Y up in the image.
#include <glm/glm.hpp>

namespace matrender {

// The largest image side the scene file and render_object accept. Larger images are no camera's;
// whether one fits in memory is checked on its own (render() refuses frame buffers that do not).
constexpr int kMaxImageSide = 65536;

struct Camera {
  glm::dmat4 camera_to_world{1.0};  // columns: +X right, +Y up, +Z backward, position
  double vertical_fov = 0.691111;   // radians (Blender's default 50 mm lens on a 36 mm sensor)
  int width = 256;
  int height = 256;

  static Camera look_at(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                        double vertical_fov, int width, int height);
};

}  // namespace matrender
