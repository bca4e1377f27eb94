#include "matdataset/maker/lighting_panorama.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "matbase/image/srgb.h"
#include "matbase/pi.h"
#include "matrender/background.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"

namespace matdataset {
namespace {

using Rgb = std::array<float, 3>;

// Where a lamp is seen from `center`, and its dot's colour.
struct LampDot {
  glm::dvec3 direction;
  Rgb colour;
};

LampDot dot_of(const matrender::Lamp& lamp, const glm::dvec3& center) {
  if (const auto* sun = std::get_if<matrender::SunLamp>(&lamp)) return {-sun->direction, {1.0f, 0.85f, 0.15f}};
  if (const auto* spot = std::get_if<matrender::SpotLamp>(&lamp)) return {spot->position - center, {1.0f, 0.5f, 0.1f}};
  if (const auto* point = std::get_if<matrender::PointLamp>(&lamp)) return {point->position - center, {1.0f, 1.0f, 1.0f}};
  const auto& rect = std::get<matrender::RectLamp>(lamp);
  return {glm::dvec3(rect.light_to_world[3]) - center, {0.3f, 0.9f, 1.0f}};
}

}  // namespace

std::vector<std::array<float, 3>> draw_lighting_panorama(const nlohmann::json& lighting, const matgeom::Sphere& bounds,
                                                         const std::filesystem::path& folder, int width, int height) {
  // The frame's lights and world exactly as the renderer had them: the scene file's reader and
  // the builder, around the object's bounding sphere (where the rig stands).
  nlohmann::json scene = {{"lights", lighting.value("lights", nlohmann::json::array())},
                          {"background", lighting.value("background", nlohmann::json::array({0, 0, 0}))}};
  const matrender::SceneLighting read = matrender::read_lighting_text(scene.dump(), "the frame's lighting", folder.string());
  matrender::BuiltScene built;
  built.bounds = bounds;
  matrender::set_scene_lighting(built, read.lights, read.background);
  const float scale = std::exp2(static_cast<float>(lighting.value("exposure_stops", 0.0)));

  std::vector<Rgb> pixels(static_cast<size_t>(width) * static_cast<size_t>(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec2 uv((x + 0.5f) / width, 1.0f - (y + 0.5f) / height);
      const glm::vec3 radiance =
          matrender::background_radiance(built.scene.background(), matrender::equirectangular_direction(uv));
      Rgb& pixel = pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
      for (int c = 0; c < 3; ++c) pixel[static_cast<size_t>(c)] = matbase::linear_to_srgb(std::clamp(radiance[c] * scale, 0.0f, 1.0f));
    }
  // Dots a twentieth of the height across, ringed in black so that they read on a bright sky.
  const float radius = std::max(1.5f, static_cast<float>(height) / 20.0f);
  for (const matrender::Lamp& lamp : built.scene.lamps()) {
    const LampDot dot = dot_of(lamp, bounds.center);
    if (!(glm::length(dot.direction) > 0.0)) continue;
    const glm::vec2 uv = matrender::equirectangular_uv(glm::vec3(glm::normalize(dot.direction)));
    const float cx = uv.x * static_cast<float>(width), cy = (1.0f - uv.y) * static_cast<float>(height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        // Across the seam the dot wraps, as the panorama does.
        float dx = std::abs(x + 0.5f - cx);
        dx = std::min(dx, static_cast<float>(width) - dx);
        const float distance = std::hypot(dx, y + 0.5f - cy);
        Rgb& pixel = pixels[static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)];
        if (distance <= radius) pixel = dot.colour;
        else if (distance <= radius + 1.0f) pixel = {0.0f, 0.0f, 0.0f};
      }
  }
  return pixels;
}

}  // namespace matdataset
