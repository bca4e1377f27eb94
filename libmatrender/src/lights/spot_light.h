#pragma once
// A spot lamp of radius 0, Cycles 3.4's conventions: a point lamp's intensity I = P c / (4 pi)
// W/sr (point_light.h) times cos t * smoothstep((cos t - cos_half) / ((1 - cos_half) blend))
// inside its cone (intern/cycles/kernel/light/spot.h, spot_attenuation; docs/conventions.md,
// Lamps), reached only by light sampling. With a radius it is a disk lamp instead (disk_light.h).
#include <cmath>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <glm/glm.hpp>

#include "lights/light_checks.h"
#include "lights/lamp_preparation.h"
#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "lights/point_light.h"
#include "matbase/pi.h"
#include "matbase/smoothstep.h"
#include "matrender/lamp.h"
#include "sampling/warp.h"
#include "util/channel_average.h"

namespace matrender {

// cos t = cosine between the lamp axis and the direction from the lamp to the lit point.
inline float spot_attenuation(float cos_t, float cos_half_angle, float blend) {
  if (cos_t <= cos_half_angle) return 0.0f;
  const float smooth_width = (1.0f - cos_half_angle) * blend;
  const float edge = smooth_width > 0.0f ? matbase::smoothstep((cos_t - cos_half_angle) / smooth_width) : 1.0f;
  return cos_t * edge;
}

class SpotLight {
 public:
  explicit SpotLight(const SpotLamp& light)
      : position_(light.position),
        intensity_(point_lamp_intensity(light.power, light.color)),
        mean_intensity_(channel_average(intensity_)),
        axis_(glm::normalize(light.direction)),
        cos_half_angle_(static_cast<float>(std::cos(0.5 * light.spot_angle))),
        blend_(static_cast<float>(light.blend)) {}

  static constexpr LightType type() { return LightType::DeltaPosition; }

  // Light selection's weight at p: the irradiance I a(w) cos / d^2 it gives, exactly (light_importance.h).
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
    const std::optional<DirectionToLamp> toward = direction_to_lamp(position_, p);
    if (!toward) return 0.0f;
    const float cosine = receiving_cosine(receiving, toward->wi);
    const float cone = spot_attenuation(glm::dot(-toward->wi, axis_), cos_half_angle_, blend_);
    return mean_intensity_ * cone * cosine / toward->distance2;
  }

  // The one direction toward the lamp; `receiving` and u play no part.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& /*receiving*/,
                                    glm::vec2 /*u*/) const {
    const std::optional<DirectionToLamp> toward = direction_to_lamp(position_, p);
    if (!toward) return std::nullopt;
    float factor = 1.0f / toward->distance2;
    factor *= spot_attenuation(glm::dot(-toward->wi, axis_), cos_half_angle_, blend_);
    if (!(factor > 0.0f)) return std::nullopt;
    return delta_light_sample(toward->wi, toward->distance, intensity_ * factor);
  }

 private:
  glm::vec3 position_;
  glm::vec3 intensity_;
  float mean_intensity_;
  glm::vec3 axis_;
  float cos_half_angle_;
  float blend_;
};

// A spot lamp renders as a disk light when it has a radius, else as a spot light.
template <>
struct LampPreparation<SpotLamp> {
  static void check(const SpotLamp& spot) {
    check_point_lamp(spot.position, spot.power, spot.color, spot.radius);
    check_direction(spot.direction);
    if (!(spot.spot_angle > 0.0 && spot.spot_angle <= matbase::kPi))
      refuse(fmt::format("spot angle {} rad must lie in (0, pi]", spot.spot_angle));
    if (!(spot.blend >= 0.0 && spot.blend <= 1.0)) refuse(fmt::format("blend {} must lie in [0, 1]", spot.blend));
  }
  template <class Add>
  static void prepare(const SpotLamp& light, Add&& add) {
    prepare_lamp_at_point<SpotLight>(light, std::forward<Add>(add));
  }
};

}  // namespace matrender
