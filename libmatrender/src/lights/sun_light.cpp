#include "lights/sun_light.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "bsdf/shading_frame.h"
#include "lights/light_checks.h"
#include "lights/light_importance.h"
#include "matbase/pi.h"
#include "sampling/warp.h"
#include "util/channel_average.h"

namespace matrender {

bool SunLight::has_disk(const SunLamp& light) {
  return static_cast<float>(std::tan(0.5 * light.angle)) > 0.0f;
}

SunLight::SunLight(const SunLamp& light)
    : to_sun_(-glm::normalize(light.direction)), irradiance_(light.strength * light.color) {
  const double radius = std::tan(0.5 * light.angle);
  disk_radius_ = static_cast<float>(radius);
  inverse_disk_area_ = static_cast<float>(1.0 / (matbase::kPi * radius * radius));
  cos_half_angle_ = static_cast<float>(std::cos(0.5 * light.angle));
  sin_half_angle_ = static_cast<float>(std::sin(0.5 * light.angle));
  mean_irradiance_ = channel_average(irradiance_);
}

float SunLight::importance(const glm::vec3& /*p*/, const ReceivingDirections& receiving) const {
  return mean_irradiance_ * receiving_bound(receiving, to_sun_, cos_half_angle_, sin_half_angle_);
}

float SunLight::density(const glm::vec3& direction) const {
  const float cos_t = glm::dot(direction, to_sun_);
  if (!(cos_t > 0.0f)) return 0.0f;
  const float sin_t = glm::length(glm::cross(direction, to_sun_));
  // A relative 1e-6 wider than the disk, so that rounding in sample() never drops a direction
  // drawn on its rim; the light is this cone throughout.
  if (!(sin_t <= disk_radius_ * cos_t * (1.0f + 1e-6f))) return 0.0f;
  return inverse_disk_area_ / (cos_t * cos_t * cos_t);
}

std::optional<LightSample> SunLight::sample(const glm::vec3& /*p*/, const ReceivingDirections& /*receiving*/,
                                                    glm::vec2 u) const {
  LightSample s;
  s.distance = std::numeric_limits<float>::infinity();
  const ShadingFrame disk = ShadingFrame::from_normal(to_sun_);
  const glm::vec2 on_disk = disk_radius_ * sample_uniform_disk_concentric(u);
  s.wi = glm::normalize(to_sun_ + disk.x * on_disk.x + disk.y * on_disk.y);
  s.pdf = density(s.wi);
  if (!(s.pdf > 0.0f)) return std::nullopt;
  s.radiance = irradiance_ * s.pdf;
  return s;
}

float SunLight::pdf(const glm::vec3& direction) const { return density(direction); }

glm::vec3 SunLight::radiance(const glm::vec3& direction) const { return irradiance_ * density(direction); }

void LampPreparation<SunLamp>::check(const SunLamp& sun) {
  check_direction(sun.direction);
  check_color(sun.color);
  if (!(std::isfinite(sun.strength) && sun.strength >= 0.0))
    refuse(fmt::format("strength {} W/m^2 must be finite and non-negative", sun.strength));
  check_emission(sun.strength * sun.color, "irradiance", "lower the strength");
  if (!(sun.angle >= 0.0 && sun.angle <= kMaxSunAngle))
    refuse(fmt::format("angle {} rad must lie in [0, {}]", sun.angle, kMaxSunAngle));
  if (sun.angle == 0.0) return;
  // The radiance E / (pi tan^2(angle / 2)) at the centre of the disk of directions.
  const double tangent = std::tan(0.5 * sun.angle);
  if (!(matbase::kPi * tangent * tangent >= kMinNormalFloat))
    refuse(fmt::format("angle {:g} rad is too small for single precision; use 0 for a single direction", sun.angle));
  check_emission(sun.strength * sun.color / (matbase::kPi * tangent * tangent), "radiance",
                 "lower the strength or widen the angle");
}

}  // namespace matrender
