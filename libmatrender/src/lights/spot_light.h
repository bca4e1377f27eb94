#pragma once
// A spot lamp of radius 0, Cycles 3.4's conventions: a point lamp's intensity I = P c / (4 pi)
// W/sr (point_light.h) times cos t * smoothstep((cos t - cos_half) / ((1 - cos_half) blend))
// inside its cone (intern/cycles/kernel/light/spot.h, spot_attenuation; docs/conventions.md,
// Lamps), reached only by light sampling. With a radius it is a disk lamp instead (disk_lamp.h).
#include <cmath>
#include <optional>

#include <glm/glm.hpp>

#include "lights/light_sample.h"
#include "lights/light_type.h"
#include "matbase/pi.h"
#include "matbase/smoothstep.h"
#include "matrender/light.h"
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

class PreparedSpotLight {
 public:
  explicit PreparedSpotLight(const SpotLight& light)
      : position_(light.position),
        intensity_(light.power * light.color / (4.0 * matbase::kPi)),
        mean_intensity_(channel_average(intensity_)),
        axis_(glm::normalize(light.direction)),
        cos_half_angle_(static_cast<float>(std::cos(0.5 * light.spot_angle))),
        blend_(static_cast<float>(light.blend)) {}

  static constexpr LightType type() { return LightType::DeltaPosition; }

  // Light selection's weight at p: the irradiance I a(w) cos / d^2 it gives, exactly (light_importance.h).
  float importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
    const glm::vec3 to_light = position_ - p;
    const float dist2 = glm::dot(to_light, to_light);
    if (!(dist2 > 0.0f)) return 0.0f;
    const glm::vec3 wi = to_light / std::sqrt(dist2);
    const float cosine = receiving.every_direction ? 1.0f : std::max(0.0f, glm::dot(wi, receiving.normal));
    const float cone = spot_attenuation(glm::dot(-wi, axis_), cos_half_angle_, blend_);
    return mean_intensity_ * cone * cosine / dist2;
  }

  // The one direction toward the lamp; `receiving` and u play no part.
  std::optional<LightSample> sample(const glm::vec3& p, const ReceivingDirections& /*receiving*/,
                                    glm::vec2 /*u*/) const {
    const glm::vec3 to_light = position_ - p;
    const float dist2 = glm::dot(to_light, to_light);
    if (!(dist2 > 0.0f)) return std::nullopt;
    const float dist = std::sqrt(dist2);
    LightSample s;
    s.wi = to_light / dist;
    s.distance = dist;
    float factor = 1.0f / dist2;
    factor *= spot_attenuation(glm::dot(-s.wi, axis_), cos_half_angle_, blend_);
    if (!(factor > 0.0f)) return std::nullopt;
    s.radiance = intensity_ * factor;
    s.pdf = 1.0f;
    s.delta = true;
    return s;
  }

 private:
  glm::vec3 position_;
  glm::vec3 intensity_;
  float mean_intensity_;
  glm::vec3 axis_;
  float cos_half_angle_;
  float blend_;
};

}  // namespace matrender
