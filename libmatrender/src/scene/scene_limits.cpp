#include "matrender/scene_limits.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace matrender {

bool within_scene_limit(const glm::dvec3& point) {
  for (int c = 0; c < 3; ++c)
    if (!(std::abs(point[c]) <= kMaxSceneCoordinate)) return false;  // NaN fails too
  return true;
}

std::optional<std::string> scene_point_problem(const glm::dvec3& point, const std::string& what) {
  if (within_scene_limit(point)) return std::nullopt;
  for (int c = 0; c < 3; ++c) {
    if (!std::isfinite(point[c])) return fmt::format("{} at ({}, {}, {}) is not a finite point", what, point.x, point.y, point.z);
    if (std::abs(point[c]) > kMaxSceneCoordinate)
      return fmt::format(
          "{} at ({}, {}, {}) lies beyond {} m of the origin, where single-precision rendering no longer "
          "resolves 8 mm; keep the scene, its lamps and the camera within that distance",
          what, point.x, point.y, point.z, kMaxSceneCoordinate);
  }
  return std::nullopt;
}

void check_scene_point(const glm::dvec3& point, const std::string& what) {
  if (const std::optional<std::string> problem = scene_point_problem(point, what)) throw std::invalid_argument(*problem);
}

}  // namespace matrender
