#pragma once
// What a scene's world is, as Blender's World shader would be: a uniform colour, or an
// equirectangular environment texture times a strength (docs/conventions.md, "Environment").
// Either is seen by camera rays that miss and lights the scene.
#include <variant>

#include <glm/glm.hpp>

#include "matrender/texture.h"

namespace matrender {

// World > Background with an Environment Texture (equirectangular, Linear interpolation) on its
// Color, Strength on its strength, and a Mapping node's Z rotation on the texture's Vector.
struct EnvironmentMap {
  TexturePtr image;         // latitude-longitude, scene-linear RGB; v = 1 is straight up (+Z)
  double strength = 1.0;
  double rotation_z = 0.0;  // radians: the map is looked up along R_z(rotation_z) d
};

// A uniform radiance (black: no world light), or an environment map.
using Background = std::variant<glm::vec3, EnvironmentMap>;

// Cycles 3.4's equirectangular mapping of a unit direction d in the map's own frame to (u, v):
// u = 0.5 - atan2(d.y, d.x) / (2 pi), v = 1 - acos(d.z) / pi (+X at the centre column, +Y a
// quarter to its left, +Z at the top row), and its inverse.
glm::vec2 equirectangular_uv(const glm::vec3& direction);
glm::vec3 equirectangular_direction(glm::vec2 uv);

// The radiance a ray leaving the scene along unit `direction` sees: the uniform colour, or the
// map's bilinear lookup (docs/conventions.md, "Environment") times its strength.
glm::vec3 background_radiance(const Background& background, const glm::vec3& direction);

}  // namespace matrender
