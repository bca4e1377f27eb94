#include "matgeom/light_rig.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "matbase/image/srgb.h"
#include "matbase/pi.h"
#include "matgeom/camera_grid.h"
#include "matgeom/lamp_irradiance.h"

namespace matgeom {
namespace {

using matbase::kPi;

// Paper: "Two additional accent lights are added on the vertical axis at +-35 degrees. If
// r > 0.15 m these accents are area lights; otherwise they are 10 degree spot lights".
constexpr double kAccentElevation = 35.0 * kPi / 180.0;
constexpr double kAccentAreaMinRadius = 0.15;  // metres; at or below it the accents are spots
constexpr double kAccentSpotAngle = 10.0 * kPi / 180.0;  // full cone, as Blender's spot_size
constexpr double kAccentSpotBlend = 0.15;                // Blender's default spot_blend

const glm::dvec3 kLampColor(0.8, 0.8, 0.8);  // paper: neutral grey-white Blender RGB

// Paper: N_theta = ceil(4 + 2 r / 0.25), 6 <= N_theta <= 12.
int ring_light_count(double radius) {
  const double unclamped = std::ceil(4.0 + 2.0 * radius / 0.25);
  return static_cast<int>(std::clamp(unclamped, 6.0, 12.0));
}

// Paper: P_base = 50 + 150 min(1, r / 1 m) watts.
double base_power(double radius) { return 50.0 + 150.0 * std::min(1.0, radius / 1.0); }

// A lamp at `position` emitting down its -Z toward `center`, its +X horizontal (the long edge
// of an area light, tangent to the circle of lamps around the vertical through `center`).
RigLight lamp_aimed_at(const glm::dvec3& position, const glm::dvec3& center) {
  RigLight light;
  light.position = position;
  // Blender lamps and cameras share the -Z-forward, +Y-up frame; world +Z up makes +X the
  // horizontal tangent.
  light.light_to_world = look_at_camera_to_world(position, center, glm::dvec3(0, 0, 1));
  light.color = kLampColor;
  return light;
}

// Radiant irradiance (W/m^2 weighted by the colour's luminance) from a rig lamp on a small surface
// at `point` with unit normal `normal`, by Cycles' conventions (docs/conventions.md, "Lamps"): an
// area lamp's radiance is P c / (4 a b), a spot's on-axis intensity P c / (4 pi).
double lamp_irradiance(const RigLight& light, const glm::dvec3& point, const glm::dvec3& normal) {
  const double power = light.power * matbase::rec709_luminance(light.color);
  if (light.kind == RigLightKind::Area)
    return rect_lamp_irradiance(light.light_to_world, light.size_x, light.size_y,
                                power / (4.0 * light.size_x * light.size_y), point, normal);
  return spot_lamp_irradiance(glm::dvec3(light.light_to_world[3]), -glm::dvec3(light.light_to_world[2]),
                              light.spot_angle, light.spot_blend, power / (4.0 * kPi), point, normal);
}

}  // namespace

// The paper asks for "E ~ 1.0 klx at c" without saying on which surface. We define the
// illuminance at a point as the sum over lamps of the illuminance each lamp gives on a small
// surface at the point facing that lamp (normal toward the lamp's centre): what a photometer
// aimed at each lamp in turn would read, summed. Radiometric watts are converted with
// 683 lm/W times the Rec.709 luminance of the lamp colour.
double rig_illuminance_lux(const std::vector<RigLight>& lights, const glm::dvec3& point) {
  double irradiance = 0.0;
  for (const RigLight& light : lights) {
    const glm::dvec3 to_lamp = glm::dvec3(light.light_to_world[3]) - point;
    const double distance = glm::length(to_lamp);
    if (distance > 0.0) irradiance += lamp_irradiance(light, point, to_lamp / distance);
  }
  return kLuxPerWattPerSquareMetre * irradiance;
}

LightRig make_light_rig(const glm::dvec3& center, double radius, const LightRigOptions& options) {
  if (!(std::isfinite(radius) && radius > 0.0)) {
    throw std::invalid_argument("make_light_rig: the radius must be positive and finite (got " +
                                std::to_string(radius) + ")");
  }
  if (!(std::isfinite(center.x) && std::isfinite(center.y) && std::isfinite(center.z))) {
    throw std::invalid_argument("make_light_rig: the centre is not finite");
  }
  if (options.target_illuminance_lux &&
      !(std::isfinite(*options.target_illuminance_lux) && *options.target_illuminance_lux > 0.0)) {
    throw std::invalid_argument(
        "make_light_rig: the target illuminance must be positive and finite");
  }

  LightRig rig;
  rig.ring_count = ring_light_count(radius);
  const double p_base = base_power(radius);
  // Paper: every lamp is 0.6 r x 0.3 r, the long edge tangent to the ring.
  const double long_edge = 0.6 * radius;
  const double short_edge = 0.3 * radius;

  // Key-fill ring: N lamps on the horizontal circle of radius 2r through c (plane z = c.z) at
  // theta_j = 2 pi j / N, each with P_j = P_base (1 + 0.3 cos theta_j).
  for (int j = 0; j < rig.ring_count; ++j) {
    const double theta = 2.0 * kPi * j / rig.ring_count;
    const glm::dvec3 position =
        center + 2.0 * radius * glm::dvec3(std::cos(theta), std::sin(theta), 0.0);
    RigLight light = lamp_aimed_at(position, center);
    light.kind = RigLightKind::Area;
    light.size_x = long_edge;
    light.size_y = short_edge;
    light.power = p_base * (1.0 + 0.3 * std::cos(theta));
    light.azimuth = theta;
    rig.lights.push_back(light);
  }

  // Accents. "On the vertical axis at +-35 degrees" is read as: at distance 2r from c (the
  // ring's distance), elevated +35 and -35 degrees from the horizontal, in the vertical plane
  // of azimuth 0 (above and below the brightest ring lamp), aimed at c. Their power is P_base:
  // the paper's cosine modulation runs over the ring's azimuths only.
  for (const double elevation : {kAccentElevation, -kAccentElevation}) {
    const glm::dvec3 position =
        center + 2.0 * radius * glm::dvec3(std::cos(elevation), 0.0, std::sin(elevation));
    RigLight light = lamp_aimed_at(position, center);
    if (radius > kAccentAreaMinRadius) {
      light.kind = RigLightKind::Area;
      light.size_x = long_edge;
      light.size_y = short_edge;
    } else {
      light.kind = RigLightKind::Spot;
      light.spot_angle = kAccentSpotAngle;
      light.spot_blend = kAccentSpotBlend;
    }
    light.power = p_base;
    light.accent = true;
    light.azimuth = 0.0;
    rig.lights.push_back(light);
  }

  rig.illuminance_lux = rig_illuminance_lux(rig.lights, center);
  if (options.target_illuminance_lux) {
    rig.power_scale = *options.target_illuminance_lux / rig.illuminance_lux;
    for (RigLight& light : rig.lights) light.power *= rig.power_scale;
    rig.illuminance_lux = rig_illuminance_lux(rig.lights, center);
  }
  return rig;
}

}  // namespace matgeom
