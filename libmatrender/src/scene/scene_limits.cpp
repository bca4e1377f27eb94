#include "matrender/scene_limits.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace matrender {

void check_scene_point(const glm::dvec3& point, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(point[c]))
      throw std::invalid_argument(fmt::format("{} at ({}, {}, {}) is not a finite point", what, point.x, point.y, point.z));
    if (std::abs(point[c]) > kMaxSceneCoordinate)
      throw std::invalid_argument(fmt::format(
          "{} at ({}, {}, {}) lies beyond {} m of the origin, where single-precision rendering no longer "
          "resolves 8 mm; keep the scene, its lamps and the camera within that distance",
          what, point.x, point.y, point.z, kMaxSceneCoordinate));
  }
}

}  // namespace matrender
