#pragma once
// What a lamp must be for single-precision shading to render it as described: finite values,
// positions within the scene limit (matrender/scene_limits.h), a rectangle whose area and
// radiance, and a point lamp whose intensity, are finite non-zero floats. Each light's
// LampPreparation::check (lamp_preparation.h) states its own with the checks below.
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "matbase/pi.h"
#include "matrender/lamp.h"

namespace matrender {

// Why the lamp cannot be rendered as given ("power 1e+308 W exceeds ..."), or nothing.
std::optional<std::string> lamp_problem(const Lamp& light);

// The checks a LampPreparation::check is made of; each refuses (throws LightRefusal) with the reason.
struct LightRefusal {
  std::string reason;
};
[[noreturn]] void refuse(const std::string& reason);
void check_point_within_limit(const glm::dvec3& point, const char* name);
void check_color(const glm::dvec3& color);  // finite, non-negative
void check_power(double power);             // watts: finite, non-negative
// An emitted radiance, intensity or irradiance the renderer keeps in floats; `remedy` says how
// to bring it within them.
void check_emission(const glm::dvec3& emission, const char* name, const char* remedy);
void check_direction(const glm::dvec3& direction);  // finite, non-zero
// A point or spot lamp; with a radius, the disk's area and radiance must fit floats too.
void check_point_lamp(const glm::dvec3& position, double power, const glm::dvec3& color, double radius);

// The smallest positive normal float: an area or solid angle below it does not divide.
constexpr double kMinNormalFloat = std::numeric_limits<float>::min();

}  // namespace matrender
