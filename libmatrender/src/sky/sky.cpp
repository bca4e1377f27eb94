#include "matrender/sky.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "matbase/image/srgb.h"
#include "sky/nishita_sky_table.h"

namespace matrender {
namespace {

// "in [0, 90]", "a finite number >= 0", "a finite number".
std::string range_text(const SkySetting& setting) {
  if (std::isfinite(setting.high))
    return fmt::format("in {}{}, {}]", setting.low_open ? "(" : "[", setting.low, setting.high);
  if (std::isfinite(setting.low)) return fmt::format("a finite number {} {}", setting.low_open ? ">" : ">=", setting.low);
  return "a finite number";
}

// What the sun lamp must add to the baked map: the disc's radiance integrated over the disc, less
// the sky's there, which the map holds and Cycles does not show behind the disc (a hazy sky is
// bright around the sun). In polar coordinates about the sun, rho = (size / 2) sin(theta), so
// that the limb's sqrt(1 - (rho / (size / 2))^2) = cos(theta) is smooth: d omega = sin(rho)
// (size / 2) cos(theta) d theta d phi, by the midpoint rule (2e-5 relative error at 128 rings;
// a square grid over the disc would be 0.2 % high at its edge).
glm::dvec3 disc_irradiance_over_sky(const NishitaSkyTable& table, double sun_size) {
  const glm::dvec3 axis = table.to_sun();
  const glm::dvec3 helper = std::abs(axis.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(helper, axis)), e2 = glm::cross(axis, e1);
  constexpr int kRings = 128, kSectors = 64;
  const double half = sun_size / 2.0, ring_step = matbase::kPi / 2.0 / kRings, sector_step = 2.0 * matbase::kPi / kSectors;
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kRings; ++i) {
    const double theta = (i + 0.5) * ring_step, rho = half * std::sin(theta);
    const double weight = std::sin(rho) * half * std::cos(theta) * ring_step * sector_step;
    for (int j = 0; j < kSectors; ++j) {
      const double phi = (j + 0.5) * sector_step;
      const glm::dvec3 d = std::cos(rho) * axis + std::sin(rho) * (std::cos(phi) * e1 + std::sin(phi) * e2);
      const glm::dvec3 disc = table.disc(d);
      if (disc != glm::dvec3(0.0)) sum += (disc - table.sky(d)) * weight;
    }
  }
  return glm::max(sum, glm::dvec3(0.0));
}

}  // namespace

const std::vector<SkySetting>& sky_settings() {
  constexpr double kDegree = matbase::kPi / 180.0, kNoLimit = std::numeric_limits<double>::infinity();
  static const std::vector<SkySetting> settings = {
      {"sun_elevation_deg", &NishitaSky::sun_elevation, kDegree, 0.0, 90.0, false, "the sun's height above the horizon"},
      {"sun_rotation_deg", &NishitaSky::sun_rotation, kDegree, -kNoLimit, kNoLimit, false,
       "the sun's turn about +Z, clockwise seen from above: 0 towards +Y, 90 towards +X"},
      {"sun_size_deg", &NishitaSky::sun_size, kDegree, 0.0, 90.0, true, "the sun disc's angular diameter"},
      {"sun_intensity", &NishitaSky::sun_intensity, 1.0, 0.0, kNoLimit, false, "the disc's radiance multiplier"},
      {"altitude_m", &NishitaSky::altitude, 1.0, 0.0, 60000.0, false, "the viewer's height above the ground"},
      {"air", &NishitaSky::air_density, 1.0, 0.0, 10.0, false, "air (Rayleigh) density, 1 = Earth's"},
      {"dust", &NishitaSky::dust_density, 1.0, 0.0, 10.0, false, "dust (Mie) density, 1 = Earth's"},
      {"ozone", &NishitaSky::ozone_density, 1.0, 0.0, 10.0, false, "ozone density, 1 = Earth's"},
  };
  return settings;
}

std::optional<std::string> sky_problem(const NishitaSky& sky) {
  for (const SkySetting& setting : sky_settings()) {
    const double value = sky.*setting.field / setting.unit;
    // Degrees come back from radians within a rounding: 90 degrees is pi / 2 and back.
    const double slack = 1e-12 * std::abs(value);
    const bool above_low = setting.low_open ? value > setting.low : value + slack >= setting.low;
    if (std::isfinite(value) && above_low && value - slack <= setting.high) continue;
    return fmt::format("{} {} is not {} ({})", setting.key, value, range_text(setting), setting.meaning);
  }
  if (!(std::isfinite(sky.strength) && sky.strength >= 0.0))
    return fmt::format("strength {} is not a finite number >= 0", sky.strength);
  return std::nullopt;
}

SkyLighting sky_lighting(const NishitaSky& sky, int map_width) {
  if (const std::optional<std::string> problem = sky_problem(sky)) throw std::invalid_argument("sky: " + *problem);
  if (map_width < 8 || map_width % 2) throw std::invalid_argument("sky: the map's width must be even and >= 8");
  const NishitaSkyTable table(sky);
  const int width = map_width, height = map_width / 2;
  std::vector<float> pixels(static_cast<size_t>(width) * height * 3);
  tbb::parallel_for(0, height, [&](int row) {
    for (int column = 0; column < width; ++column) {
      // Texel centres, rows top to bottom (Texture::from_pixelsf), mapped as the renderer maps.
      const glm::vec2 uv((column + 0.5f) / width, 1.0f - (row + 0.5f) / height);
      const glm::dvec3 radiance = table.sky(glm::dvec3(equirectangular_direction(uv)));
      for (int c = 0; c < 3; ++c) pixels[(static_cast<size_t>(row) * width + column) * 3 + c] = static_cast<float>(radiance[c]);
    }
  });
  SkyLighting lighting;
  lighting.map.image =
      Texture::from_pixelsf(width, height, 3, pixels.data(), ColorSpace::NonColor, TextureWrap::Repeat, "Nishita sky");
  lighting.map.strength = sky.strength;
  const glm::dvec3 irradiance = disc_irradiance_over_sky(table, sky.sun_size) * sky.strength;
  const double luminance = matbase::rec709_luminance(irradiance);
  if (luminance > 0.0) {
    SunLamp sun;
    sun.direction = -table.to_sun();
    sun.angle = sky.sun_size;
    sun.strength = luminance;
    sun.color = irradiance / luminance;
    lighting.sun = sun;
  }
  return lighting;
}

}  // namespace matrender
