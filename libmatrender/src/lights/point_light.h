#pragma once
// A point lamp of radius 0, Cycles 3.4's conventions (intern/cycles/kernel/light/point.h;
// docs/conventions.md, Lamps): intensity I = P c / (4 pi) W/sr in every direction, reached only by
// light sampling. With a radius it is a disk lamp instead (disk_light.h).
#include <cmath>
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "lights/disk_light.h"
#include "lights/light_checks.h"
#include "lights/lamp_preparation.h"
#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matbase/pi.h"
#include "matrender/lamp.h"
#include "util/channel_average.h"

namespace matrender {

// A lamp at a point seen from p: the unit direction toward it, the distance and its square;
// nothing from the lamp's own position.
struct DirectionToLamp {
  glm::vec3 wi;
  float distance;
  float distance2;
};
inline std::optional<DirectionToLamp> direction_to_lamp(const glm::vec3& position, const glm::vec3& p) {
  const glm::vec3 to_light = position - p;
  const float distance2 = glm::dot(to_light, to_light);
  if (!(distance2 > 0.0f)) return std::nullopt;
  const float distance = std::sqrt(distance2);
  return DirectionToLamp{to_light / distance, distance, distance2};
}

// The cosine at which the receiving side takes light from wi: 1 for a BSDF that transmits.
inline float receiving_cosine(const ReceivingDirections& receiving, const glm::vec3& wi) {
  return receiving.every_direction ? 1.0f : std::max(0.0f, glm::dot(wi, receiving.normal));
}

// A point lamp's intensity I = P c / (4 pi), W/sr.
inline glm::vec3 point_lamp_intensity(double power, const glm::dvec3& color) {
  return power * color / (4.0 * matbase::kPi);
}

class PointLight {
 public:
  explicit PointLight(const PointLamp& light)
      : position_(light.position),
        intensity_(point_lamp_intensity(light.power, light.color)),
        mean_intensity_(channel_average(intensity_)) {}

  static constexpr LightType type() { return LightType::DeltaPosition; }

  // Light selection's weight at p: the irradiance I cos / d^2 it gives, exactly (light_importance.h).
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
    const std::optional<DirectionToLamp> toward = direction_to_lamp(position_, p);
    if (!toward) return 0.0f;
    return mean_intensity_ * receiving_cosine(receiving, toward->wi) / toward->distance2;
  }

  // The one direction toward the lamp; `receiving` and u play no part.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& /*receiving*/,
                                    glm::vec2 /*u*/) const {
    const std::optional<DirectionToLamp> toward = direction_to_lamp(position_, p);
    if (!toward) return std::nullopt;
    const float factor = 1.0f / toward->distance2;
    if (!(factor > 0.0f)) return std::nullopt;
    return delta_light_sample(toward->wi, toward->distance, intensity_ * factor);
  }

 private:
  glm::vec3 position_;
  glm::vec3 intensity_;
  float mean_intensity_;
};

// A lamp at a point renders as a disk lamp when it has a radius, else as `Delta`.
template <class Delta, class LampAtPoint, class Add>
void prepare_lamp_at_point(const LampAtPoint& light, Add&& add) {
  if (light.radius > 0.0)
    std::forward<Add>(add)(DiskLight(light));
  else
    std::forward<Add>(add)(Delta(light));
}

// A point lamp renders as a disk light when it has a radius, else as a point light.
template <>
struct LampPreparation<PointLamp> {
  static void check(const PointLamp& light) {
    check_point_lamp(light.position, light.power, light.color, light.radius);
  }
  template <class Add>
  static void prepare(const PointLamp& light, Add&& add) {
    prepare_lamp_at_point<PointLight>(light, std::forward<Add>(add));
  }
};

}  // namespace matrender
