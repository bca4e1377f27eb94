#pragma once
// Lamps with Blender 3.4 Cycles power conventions (docs/conventions.md, "Lamps").
// Lamps never occlude; camera rays see only area lamps made visible to them (Blender's default:
// none). Radius-0 point and spot lamps and suns of angle 0 are reached by light sampling only.
#include <variant>

#include <glm/glm.hpp>

#include "matbase/pi.h"

namespace matrender {

// One-sided rectangle emitting down its local -Z; radiance L = power * color / (4 a b).
struct RectLamp {
  glm::dmat4 light_to_world{1.0};  // columns: +X (size_x edge), +Y (size_y edge), +Z, centre
  double size_x = 1.0;
  double size_y = 1.0;
  double power = 10.0;  // Blender watts
  glm::dvec3 color{1.0};
  // Blender's Object > Visibility > Camera: the camera sees the lamp's emitting side.
  bool visible_to_camera = false;
};

// Point lamp: intensity I = power * color / (4 pi) W/sr. With a radius R > 0, Cycles 3.4's soft
// point lamp: a disk of radius R facing the lit point, radiance I / (pi R^2), which rays also hit.
struct PointLamp {
  glm::dvec3 position{0.0};
  double power = 10.0;
  glm::dvec3 color{1.0};
  double radius = 0.0;  // metres (Blender's Radius)
};

// Spot lamp along `direction`: a point lamp's I on the axis, times
// cos t * smoothstep((cos t - cos(angle/2)) / ((1 - cos(angle/2)) * blend)) inside the cone, for t
// the angle from the axis to the lit point (from the sampled point of the disk when R > 0).
struct SpotLamp {
  glm::dvec3 position{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
  double spot_angle = 0.7853981633974483;  // full cone angle, radians (Blender's spot_size)
  double blend = 0.15;
  double power = 10.0;
  glm::dvec3 color{1.0};
  double radius = 0.0;  // metres (Blender's Radius)
};

// Sun: parallel light from one direction; irradiance strength * color (W/m^2) on a surface facing
// it. With an angular diameter > 0, Cycles 3.4's soft sun: the directions of a disk of radius
// tan(angle / 2) at distance 1, radiance E / (pi tan^2(angle / 2) cos^3 t) at angle t off its axis.
struct SunLamp {
  glm::dvec3 direction{0.0, 0.0, -1.0};  // the way its light travels (the lamp's -Z)
  double strength = 1.0;                  // W/m^2 (Blender's Strength)
  glm::dvec3 color{1.0};
  double angle = 0.0;  // angular diameter, radians (Blender's Angle), below 180 degrees
};

// The widest sun: Blender takes 180 degrees, where the disk of directions, of radius
// tan(angle / 2), becomes infinite; at 179 degrees it is 115 wide.
constexpr double kMaxSunAngle = 179.0 * matbase::kPi / 180.0;

using Lamp = std::variant<RectLamp, PointLamp, SpotLamp, SunLamp>;

}  // namespace matrender
