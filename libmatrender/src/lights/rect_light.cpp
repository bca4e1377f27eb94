#include "lights/rect_light.h"

#include <cmath>

#include "lights/spherical_rectangle.h"

namespace matrender {
namespace {

// Below this solid angle the spherical-rectangle setup loses too many digits to cancellation;
// the lamp is then so small as seen from p that area sampling is as good.
constexpr double kMinSphericalSolidAngle = 1e-5;

}  // namespace

PreparedRectLight::PreparedRectLight(const RectLight& light) {
  const glm::dvec3 axis_x = glm::normalize(glm::dvec3(light.light_to_world[0]));
  const glm::dvec3 axis_y = glm::normalize(glm::dvec3(light.light_to_world[1]));
  emit_dir_ = -glm::normalize(glm::cross(axis_x, axis_y));
  center_ = glm::dvec3(light.light_to_world[3]);
  edge_x_ = axis_x * light.size_x;
  edge_y_ = axis_y * light.size_y;
  corner_ = center_ - 0.5 * edge_x_ - 0.5 * edge_y_;
  area_ = light.size_x * light.size_y;
  radiance_ = glm::vec3(light.power * light.color / (4.0 * area_));
  center_f_ = glm::vec3(center_);
  emit_dir_f_ = glm::vec3(emit_dir_);
  axis_x_f_ = glm::vec3(axis_x);
  axis_y_f_ = glm::vec3(axis_y);
  half_x_f_ = static_cast<float>(0.5 * light.size_x);
  half_y_f_ = static_cast<float>(0.5 * light.size_y);
}

bool PreparedRectLight::sees_emitting_side(const glm::dvec3& p) const {
  return glm::dot(p - center_, emit_dir_) > 0.0;
}

std::optional<LightSample> PreparedRectLight::sample(const glm::vec3& p_float, glm::vec2 u) const {
  const glm::dvec3 p(p_float);
  if (!sees_emitting_side(p)) return std::nullopt;
  const SphericalRectangle spherical(p, corner_, edge_x_, edge_y_);
  glm::dvec3 point;
  double pdf;
  if (spherical.solid_angle() > kMinSphericalSolidAngle) {
    point = spherical.sample(glm::dvec2(u));
    pdf = 1.0 / spherical.solid_angle();
  } else {
    point = corner_ + double(u.x) * edge_x_ + double(u.y) * edge_y_;
    const glm::dvec3 to_light = point - p;
    const double dist2 = glm::dot(to_light, to_light);
    const double cos_light = glm::dot(-to_light, emit_dir_) / std::sqrt(dist2);
    if (!(cos_light > 0.0)) return std::nullopt;
    pdf = dist2 / (cos_light * area_);
  }
  const glm::dvec3 to_light = point - p;
  const double dist = glm::length(to_light);
  if (!(dist > 0.0) || !std::isfinite(pdf)) return std::nullopt;
  LightSample s;
  s.wi = glm::vec3(to_light / dist);
  s.distance = static_cast<float>(dist);
  s.radiance = radiance_;
  s.pdf = static_cast<float>(pdf);
  s.delta = false;
  return s;
}

float PreparedRectLight::pdf(const glm::vec3& p_float, const glm::vec3& wi, float t) const {
  const glm::dvec3 p(p_float);
  if (!sees_emitting_side(p)) return 0.0f;
  const SphericalRectangle spherical(p, corner_, edge_x_, edge_y_);
  if (spherical.solid_angle() > kMinSphericalSolidAngle) return static_cast<float>(1.0 / spherical.solid_angle());
  const double cos_light = -glm::dot(glm::dvec3(wi), emit_dir_);
  if (!(cos_light > 0.0)) return 0.0f;
  return static_cast<float>(double(t) * double(t) / (cos_light * area_));
}

std::optional<float> PreparedRectLight::intersect(const glm::vec3& origin, const glm::vec3& dir,
                                                  float t_max) const {
  const float facing = glm::dot(dir, emit_dir_f_);
  if (!(facing < 0.0f)) return std::nullopt;  // only the emitting side is visible
  const float t = glm::dot(center_f_ - origin, emit_dir_f_) / facing;
  if (!(t > 0.0f) || t >= t_max) return std::nullopt;
  const glm::vec3 local = origin + t * dir - center_f_;
  if (std::abs(glm::dot(local, axis_x_f_)) > half_x_f_ || std::abs(glm::dot(local, axis_y_f_)) > half_y_f_)
    return std::nullopt;
  return t;
}

}  // namespace matrender
