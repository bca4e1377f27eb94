#pragma once
// A sun of angular diameter 0, Cycles 3.4's distant lamp (kernel/light/light.h, LIGHT_DISTANT):
// parallel light from one direction, of irradiance E = S c on a surface facing it, reached only by
// light sampling (pbrt-v4's DistantLight). A sun with an angle is a disk of directions instead
// (sun_light.h).
#include <limits>
#include <optional>

#include <glm/glm.hpp>

#include "lights/light_importance.h"
#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matrender/lamp.h"
#include "util/channel_average.h"

namespace matrender {

class DistantLight {
 public:
  explicit DistantLight(const SunLamp& light)
      : to_sun_(-glm::normalize(light.direction)),
        irradiance_(light.strength * light.color),
        mean_irradiance_(channel_average(irradiance_)) {}

  static constexpr LightType type() { return LightType::DeltaDirection; }

  // Light selection's weight: E times the receiving plane's cosine toward the sun.
  float importance(const glm::vec3& /*p*/, const ReceivingDirections& receiving) const {
    return mean_irradiance_ * receiving_bound(receiving, to_sun_, 1.0f, 0.0f);
  }

  // The sun's one direction, unless the receiving plane faces away from it; p and u play no part.
  std::optional<LightSample> sample(const glm::vec3& /*p*/, const ReceivingDirections& receiving,
                                    glm::vec2 /*u*/) const {
    if (!receiving.every_direction && !(glm::dot(to_sun_, receiving.normal) > 0.0f)) return std::nullopt;
    return delta_light_sample(to_sun_, std::numeric_limits<float>::infinity(), irradiance_);
  }

 private:
  glm::vec3 to_sun_;
  glm::vec3 irradiance_;
  float mean_irradiance_;
};

}  // namespace matrender
