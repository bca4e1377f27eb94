#pragma once
// Lamps with Blender 3.4 Cycles power conventions (docs/conventions.md, "Lamps").
// Lamps never occlude; camera rays see only area lamps made visible to them (Blender's default:
// none).
#include <variant>

#include <glm/glm.hpp>

namespace matrender {

// One-sided rectangle emitting down its local -Z; radiance L = power * color / (4 a b).
struct RectLight {
  glm::dmat4 light_to_world{1.0};  // columns: +X (size_x edge), +Y (size_y edge), +Z, centre
  double size_x = 1.0;
  double size_y = 1.0;
  double power = 10.0;  // Blender watts
  glm::dvec3 color{1.0};
  // Blender's Object > Visibility > Camera: the camera sees the lamp's emitting side.
  bool visible_to_camera = false;
};

// Radius-0 point lamp: intensity I = power * color / (4 pi) W/sr.
struct PointLight {
  glm::dvec3 position{0.0};
  double power = 10.0;
  glm::dvec3 color{1.0};
};

// Radius-0 spot lamp along `direction`: I = power * color / (4 pi) on the axis, times
// cos t * smoothstep((cos t - cos(angle/2)) / ((1 - cos(angle/2)) * blend)) inside the cone.
struct SpotLight {
  glm::dvec3 position{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
  double spot_angle = 0.7853981633974483;  // full cone angle, radians (Blender's spot_size)
  double blend = 0.15;
  double power = 10.0;
  glm::dvec3 color{1.0};
};

using Light = std::variant<RectLight, PointLight, SpotLight>;

}  // namespace matrender
