#pragma once
// The uniform background: the same radiance from every direction no surface blocks (Blender's
// plain world colour). Cycles 3.4 leaves a world without spatial variation out of light sampling
// (scene/light.cpp, test_enabled_lights: "Background MIS has been disabled"), so it is found only
// by rays that leave the scene, with MIS weight 1. An environment map would be sampled instead.
#include <optional>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/light_type.h"

namespace matrender {

class UniformBackground {
 public:
  explicit UniformBackground(const glm::vec3& radiance) : radiance_(radiance) {}

  static constexpr LightType type() { return LightType::Infinite; }
  static constexpr bool visible_to_camera() { return true; }
  static constexpr bool same_radiance_everywhere() { return true; }
  // Not part of the light-sampling distribution (LightSampler leaves it out): no sample, and a
  // density of 0 everywhere, so a ray that escapes takes its radiance with MIS weight 1.
  std::optional<LightSample> sample(const glm::vec3&, const ReceivingDirections&, glm::vec2) const {
    return std::nullopt;
  }
  float pdf(const glm::vec3& /*direction*/) const { return 0.0f; }
  float importance(const glm::vec3&, const ReceivingDirections&) const { return 0.0f; }
  glm::vec3 radiance(const glm::vec3& /*direction*/) const { return radiance_; }

 private:
  glm::vec3 radiance_;
};

}  // namespace matrender
