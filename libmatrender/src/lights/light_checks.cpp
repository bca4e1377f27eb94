#include "lights/light_checks.h"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "matbase/pi.h"
#include "matrender/scene_limits.h"
#include "util/finite.h"

namespace matrender {
namespace {

constexpr double kMaxFloat = std::numeric_limits<float>::max();
constexpr double kMinNormalFloat = std::numeric_limits<float>::min();

// Carries a reason out of the checks below.
struct Refusal {
  std::string reason;
};

[[noreturn]] void refuse(const std::string& reason) { throw Refusal{reason}; }

void check_point_within_limit(const glm::dvec3& point, const char* name) {
  if (const std::optional<std::string> problem = scene_point_problem(point, name)) refuse(*problem);
}

void check_color(const glm::dvec3& color) {
  for (int c = 0; c < 3; ++c)
    if (!(std::isfinite(color[c]) && color[c] >= 0.0))
      refuse(fmt::format("colour ({}, {}, {}) must be finite and non-negative", color.r, color.g, color.b));
}

void check_power(double power) {
  if (!(std::isfinite(power) && power >= 0.0)) refuse(fmt::format("power {} W must be finite and non-negative", power));
}

// The emitted radiance or intensity the renderer keeps in floats.
void check_emission(const glm::dvec3& emission, const char* name, const char* remedy) {
  for (int c = 0; c < 3; ++c)
    if (!(emission[c] <= kMaxFloat))
      refuse(fmt::format("its {} {:g} exceeds single precision's {:g}; {}", name, emission[c], kMaxFloat, remedy));
}

void check_rect(const RectLight& light) {
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
    refuse(fmt::format("its area {:g} m^2 ({} x {} m) is below the {:g} single precision holds", area,
                             light.size_x, light.size_y, kMinNormalFloat));
  check_color(light.color);
  check_power(light.power);
  check_emission(light.power * light.color / (4.0 * area), "radiance", "lower the power or enlarge the lamp");
}

void check_direction(const glm::dvec3& direction) {
  if (!(glm::length(direction) > 0.0) || !std::isfinite(glm::length(direction)))
    refuse("its direction must be a finite non-zero vector");
}

// A point or spot lamp; with a radius, the disk's area and radiance must fit floats too.
void check_point(const glm::dvec3& position, double power, const glm::dvec3& color, double radius) {
  check_point_within_limit(position, "position");
  check_color(color);
  check_power(power);
  check_emission(power * color / (4.0 * matbase::kPi), "intensity", "lower the power");
  if (!(std::isfinite(radius) && radius >= 0.0)) refuse(fmt::format("radius {} m must be finite and >= 0", radius));
  if (radius > kMaxSceneCoordinate) refuse(fmt::format("radius {} m exceeds the scene's {} m", radius, kMaxSceneCoordinate));
  if (radius == 0.0) return;
  const double area = matbase::kPi * radius * radius;
  if (!(area >= kMinNormalFloat))
    refuse(fmt::format("its disk's area {:g} m^2 (radius {} m) is below the {:g} single precision holds", area, radius,
                       kMinNormalFloat));
  check_emission(power * color / (4.0 * matbase::kPi * area), "radiance", "lower the power or enlarge the radius");
}

void check_spot(const SpotLight& spot) {
  check_point(spot.position, spot.power, spot.color, spot.radius);
  check_direction(spot.direction);
  if (!(spot.spot_angle > 0.0 && spot.spot_angle <= matbase::kPi))
    refuse(fmt::format("spot angle {} rad must lie in (0, pi]", spot.spot_angle));
  if (!(spot.blend >= 0.0 && spot.blend <= 1.0)) refuse(fmt::format("blend {} must lie in [0, 1]", spot.blend));
}

void check_sun(const SunLight& sun) {
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

}  // namespace

std::optional<std::string> light_problem(const Light& light) {
  try {
    if (const auto* rect = std::get_if<RectLight>(&light)) check_rect(*rect);
    if (const auto* point = std::get_if<PointLight>(&light))
      check_point(point->position, point->power, point->color, point->radius);
    if (const auto* spot = std::get_if<SpotLight>(&light)) check_spot(*spot);
    if (const auto* sun = std::get_if<SunLight>(&light)) check_sun(*sun);
  } catch (const Refusal& refusal) {
    return refusal.reason;
  }
  return std::nullopt;
}

}  // namespace matrender
