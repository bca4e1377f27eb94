#pragma once
// The scene's world as a light: a uniform background or an environment map, prepared once when
// the scene's background is set, so that renders of many views share the map's sampling density.
#include <variant>

#include "lights/environment_light.h"
#include "lights/uniform_background.h"
#include "matrender/background.h"

namespace matrender {

using WorldLight = std::variant<UniformBackground, EnvironmentLight>;

inline WorldLight prepare_world(const Background& background) {
  if (const auto* map = std::get_if<EnvironmentMap>(&background)) return EnvironmentLight(*map);
  return UniformBackground(std::get<glm::vec3>(background));
}

}  // namespace matrender
