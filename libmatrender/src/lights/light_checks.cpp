#include "lights/light_checks.h"

#include <cmath>
#include <limits>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "matbase/pi.h"
#include "matrender/scene_limits.h"
#include "lights/light.h"

namespace matrender {
namespace {

constexpr double kMaxFloat = std::numeric_limits<float>::max();

}  // namespace

void refuse(const std::string& reason) { throw LightRefusal{reason}; }

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

void check_emission(const glm::dvec3& emission, const char* name, const char* remedy) {
  for (int c = 0; c < 3; ++c)
    if (!(emission[c] <= kMaxFloat))
      refuse(fmt::format("its {} {:g} exceeds single precision's {:g}; {}", name, emission[c], kMaxFloat, remedy));
}

void check_direction(const glm::dvec3& direction) {
  if (!(glm::length(direction) > 0.0) || !std::isfinite(glm::length(direction)))
    refuse("its direction must be a finite non-zero vector");
}

void check_point_lamp(const glm::dvec3& position, double power, const glm::dvec3& color, double radius) {
  check_point_within_limit(position, "position");
  check_color(color);
  check_power(power);
  check_emission(power * color / (4.0 * matbase::kPi), "intensity", "lower the power");
  if (!(std::isfinite(radius) && radius >= 0.0)) refuse(fmt::format("radius {} m must be finite and >= 0", radius));
  if (radius > kMaxSceneCoordinate)
    refuse(fmt::format("radius {} m exceeds the scene's {} m", radius, kMaxSceneCoordinate));
  if (radius == 0.0) return;
  const double area = matbase::kPi * radius * radius;
  if (!(area >= kMinNormalFloat))
    refuse(fmt::format("its disk's area {:g} m^2 (radius {} m) is below the {:g} single precision holds", area, radius,
                       kMinNormalFloat));
  check_emission(power * color / (4.0 * matbase::kPi * area), "radiance", "lower the power or enlarge the radius");
}

std::optional<std::string> lamp_problem(const Lamp& light) {
  try {
    std::visit([](const auto& described) { LampPreparation<std::decay_t<decltype(described)>>::check(described); }, light);
  } catch (const LightRefusal& refusal) {
    return refusal.reason;
  }
  return std::nullopt;
}

}  // namespace matrender
