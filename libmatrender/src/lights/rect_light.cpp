#include "lights/rect_light.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "lights/light_checks.h"
#include "lights/light_importance.h"
#include "matrender/scene_limits.h"
#include "util/channel_average.h"
#include "util/finite.h"

namespace matrender {
namespace {

// Below this solid angle (a lamp under about 2 degrees across) single-precision spherical
// sampling quantises the lamp into few columns; area sampling is then as good and exact.
constexpr float kMinSphericalSolidAngle = 1e-3f;

}  // namespace

RectLight::RectLight(const RectLamp& light) {
  const glm::dvec3 axis_x = glm::normalize(glm::dvec3(light.light_to_world[0]));
  const glm::dvec3 axis_y = glm::normalize(glm::dvec3(light.light_to_world[1]));
  const glm::dvec3 center(light.light_to_world[3]);
  rect_.x = glm::vec3(axis_x);
  rect_.y = glm::vec3(axis_y);
  rect_.z = glm::vec3(glm::normalize(glm::cross(axis_x, axis_y)));
  rect_.length_x = static_cast<float>(light.size_x);
  rect_.length_y = static_cast<float>(light.size_y);
  rect_.corner = glm::vec3(center - 0.5 * light.size_x * axis_x - 0.5 * light.size_y * axis_y);
  center_ = glm::vec3(center);
  const glm::vec3 edge_x = rect_.length_x * rect_.x, edge_y = rect_.length_y * rect_.y;
  corners_ = {rect_.corner, rect_.corner + edge_x, rect_.corner + edge_x + edge_y, rect_.corner + edge_y};
  area_ = static_cast<float>(light.size_x * light.size_y);
  radiance_ = glm::vec3(light.power * light.color / (4.0 * light.size_x * light.size_y));
  visible_to_camera_ = light.visible_to_camera;
  bounding_radius_ = static_cast<float>(0.5 * std::sqrt(light.size_x * light.size_x + light.size_y * light.size_y));
  power_ = channel_average(radiance_) * area_;
}

float RectLight::importance(const glm::vec3& p, const ReceivingDirections& receiving) const {
  return one_sided_emitter_importance(center_, rect_.z, bounding_radius_, power_, p, receiving);
}

bool RectLight::sees_emitting_side(const glm::vec3& p) const {
  return glm::dot(p - center_, rect_.z) < 0.0f;
}

bool RectLight::below_plane(const glm::vec3& p, const glm::vec3& n) const {
  for (const glm::vec3& corner : corners_)
    if (glm::dot(corner - p, n) > 0.0f) return false;
  return true;
}

std::optional<LightSample> RectLight::sample(const glm::vec3& p, const ReceivingDirections& receiving,
                                                     glm::vec2 u) const {
  if (!sees_emitting_side(p) || (!receiving.every_direction && below_plane(p, receiving.normal)))
    return std::nullopt;
  const SphericalRectangle spherical(p, rect_);
  glm::vec3 point;
  float pdf;
  if (spherical.solid_angle() > kMinSphericalSolidAngle) {
    point = spherical.sample(u);
    pdf = 1.0f / spherical.solid_angle();
  } else {
    point = rect_.corner + (u.x * rect_.length_x) * rect_.x + (u.y * rect_.length_y) * rect_.y;
    const glm::vec3 to_light = point - p;
    const float dist2 = glm::dot(to_light, to_light);
    const float cos_light = glm::dot(to_light, rect_.z) / std::sqrt(dist2);
    if (!(cos_light > 0.0f)) return std::nullopt;
    pdf = dist2 / (cos_light * area_);
  }
  const glm::vec3 to_light = point - p;
  const float dist = glm::length(to_light);
  if (!(dist > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
  LightSample s;
  s.wi = to_light / dist;
  s.distance = dist;
  s.radiance = radiance_;
  s.pdf = pdf;
  return s;
}

float RectLight::pdf(const glm::vec3& p, const glm::vec3& wi, float t) const {
  if (!sees_emitting_side(p)) return 0.0f;
  const float solid_angle = SphericalRectangle(p, rect_).solid_angle();
  if (solid_angle > kMinSphericalSolidAngle) return 1.0f / solid_angle;
  const float cos_light = glm::dot(wi, rect_.z);
  if (!(cos_light > 0.0f)) return 0.0f;
  return t * t / (cos_light * area_);
}

void LampPreparation<RectLamp>::check(const RectLamp& light) {
  if (!is_finite(light.light_to_world)) refuse("its transform has a non-finite entry");
  check_point_within_limit(glm::dvec3(light.light_to_world[3]), "centre");
  const glm::dvec3 axis_x(light.light_to_world[0]), axis_y(light.light_to_world[1]);
  if (!(glm::length(glm::cross(axis_x, axis_y)) > 0.0))
    refuse("its transform's X and Y axes are zero or parallel, so the rectangle has no plane");
  for (const double size : {light.size_x, light.size_y}) {
    if (!(std::isfinite(size) && size > 0.0)) refuse(fmt::format("size {} m must be finite and positive", size));
    if (size > 2.0 * kMaxSceneCoordinate)
      refuse(fmt::format("size {} m exceeds the scene's {} m", size, 2.0 * kMaxSceneCoordinate));
  }
  const double area = light.size_x * light.size_y;
  if (!(area >= kMinNormalFloat))
    refuse(fmt::format("its area {:g} m^2 ({} x {} m) is below the {:g} single precision holds", area, light.size_x,
                       light.size_y, kMinNormalFloat));
  check_color(light.color);
  check_power(light.power);
  check_emission(light.power * light.color / (4.0 * area), "radiance", "lower the power or enlarge the lamp");
}

}  // namespace matrender
