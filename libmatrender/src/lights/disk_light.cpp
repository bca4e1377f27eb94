#include "lights/disk_light.h"

#include <cmath>

#include "bsdf/shading_frame.h"
#include "lights/light_importance.h"
#include "lights/spot_light.h"
#include "matbase/pi.h"
#include "sampling/warp.h"
#include "util/channel_average.h"

namespace matrender {
namespace {

glm::vec3 disk_radiance(double power, const glm::dvec3& color, double radius) {
  return glm::vec3(power * color / (4.0 * matbase::kPi * matbase::kPi * radius * radius));
}

}  // namespace

DiskLight::DiskLight(const PointLamp& light)
    : center_(light.position),
      radius_(static_cast<float>(light.radius)),
      radiance_(disk_radiance(light.power, light.color, light.radius)),
      intensity_(static_cast<float>(light.power / (4.0 * matbase::kPi)) * channel_average(glm::vec3(light.color))) {}

DiskLight::DiskLight(const SpotLamp& light)
    : center_(light.position),
      radius_(static_cast<float>(light.radius)),
      radiance_(disk_radiance(light.power, light.color, light.radius)),
      intensity_(static_cast<float>(light.power / (4.0 * matbase::kPi)) * channel_average(glm::vec3(light.color))),
      axis_(glm::normalize(light.direction)),
      cos_half_angle_(static_cast<float>(std::cos(0.5 * light.spot_angle))),
      blend_(static_cast<float>(light.blend)),
      is_spot_(true) {}

glm::vec3 DiskLight::radiance(const glm::vec3& dir) const {
  if (!is_spot_) return radiance_;
  return radiance_ * spot_attenuation(glm::dot(-dir, axis_), cos_half_angle_, blend_);
}

std::optional<LightSample> DiskLight::sample(const glm::vec3& p, const ReceivingDirections& receiving,
                                                    glm::vec2 u) const {
  const glm::vec3 to_p = p - center_;
  const float d = glm::length(to_p);
  if (!(d > 0.0f)) return std::nullopt;
  // Every point of the disk lies within radius_ of the centre.
  if (!receiving.every_direction && glm::dot(center_ - p, receiving.normal) + radius_ <= 0.0f) return std::nullopt;
  const glm::vec3 facing = to_p / d;
  const ShadingFrame disk = ShadingFrame::from_normal(facing);
  const glm::vec2 on_disk = radius_ * sample_uniform_disk_concentric(u);
  const glm::vec3 to_light = center_ + disk.x * on_disk.x + disk.y * on_disk.y - p;
  LightSample s;
  s.distance = glm::length(to_light);
  if (!(s.distance > 0.0f)) return std::nullopt;
  s.wi = to_light / s.distance;
  s.radiance = radiance(s.wi);
  if (!(s.radiance.x + s.radiance.y + s.radiance.z > 0.0f)) return std::nullopt;
  s.pdf = pdf(p, s.wi, s.distance);
  if (!(s.pdf > 0.0f) || std::isinf(s.pdf)) return std::nullopt;
  return s;
}

float DiskLight::importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
  const glm::vec3 to_center = center_ - p;
  const float distance2 = glm::dot(to_center, to_center);
  const float distance = std::sqrt(distance2);
  if (!(distance > 0.0f)) return 0.0f;
  const SubtendedCone cone(radius_, distance);
  return intensity_ * receiving_bound(receiving, to_center / distance, cone.cos_s, cone.sin_s) /
         std::max(distance2, radius_ * radius_);
}

float DiskLight::pdf(const glm::vec3& p, const glm::vec3& wi, float t) const {
  const glm::vec3 facing = glm::normalize(p - center_);
  const float cos_light = -glm::dot(facing, wi);
  if (!(cos_light > 0.0f)) return 0.0f;
  // Area density 1 / (pi R^2) times the area-to-solid-angle factor t^2 / cos.
  return t * t / (cos_light * kPi * radius_ * radius_);
}

std::optional<float> DiskLight::intersect(const glm::vec3& origin, const glm::vec3& dir, float t_max) const {
  const glm::vec3 from_center = origin - center_;
  const float height = glm::length(from_center);
  if (!(height > 0.0f)) return std::nullopt;
  const glm::vec3 facing = from_center / height;
  const float approach = -glm::dot(dir, facing);
  if (!(approach > 0.0f)) return std::nullopt;
  const float t = height / approach;
  if (!(t > 0.0f && t < t_max)) return std::nullopt;
  const glm::vec3 offset = from_center + t * dir;
  if (!(glm::dot(offset, offset) <= radius_ * radius_)) return std::nullopt;
  return t;
}

}  // namespace matrender
