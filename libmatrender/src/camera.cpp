#include "matrender/camera.h"

#include "matgeom/camera_grid.h"

namespace matrender {

Camera Camera::look_at(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up,
                       double vertical_fov, int width, int height) {
  Camera camera;
  camera.camera_to_world = matgeom::look_at_camera_to_world(eye, target, up);
  camera.vertical_fov = vertical_fov;
  camera.width = width;
  camera.height = height;
  return camera;
}

}  // namespace matrender
