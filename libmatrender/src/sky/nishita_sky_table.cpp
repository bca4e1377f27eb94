#include "sky/nishita_sky_table.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "color/cie_xyz.h"
#include "sky/nishita_atmosphere.h"

namespace matrender {
namespace {

constexpr double kPi = matbase::kPi;

// A direction at `elevation` above the horizon and `azimuth` counterclockwise from +X.
glm::dvec3 direction_at(double elevation, double azimuth) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth), std::sin(elevation)};
}

// Cycles 3.4 clamps the altitude: below 1 m the model is unstable, above 60 km is space.
double evaluated_altitude(double altitude) { return std::clamp(altitude, 1.0, 59999.0); }

// The sun's azimuth from +X, counterclockwise, for Blender's rotation (clockwise from +Y).
double sun_azimuth(double rotation) { return kPi / 2.0 - rotation; }

double fraction(double x) { return x - std::floor(x); }

// Cycles' xyz_to_rgb_clamped: scene-linear Rec.709, negative components (colours outside its
// gamut) set to 0.
glm::dvec3 clamped_rgb(const glm::dvec3& xyz) { return glm::max(xyz_to_linear_rec709(xyz), glm::dvec3(0.0)); }

}  // namespace

NishitaSkyTable::NishitaSkyTable(const NishitaSky& sky)
    : sky_(sky), to_sun_(direction_at(sky.sun_elevation, sun_azimuth(sky.sun_rotation))), xyz_(kWidth * kHeight) {
  const AtmosphereDensities densities{sky.air_density, sky.dust_density, sky.ozone_density};
  const double altitude = evaluated_altitude(sky.altitude);
  // In the table's own frame the sun lies along azimuth 0; the table is symmetric about it.
  const glm::dvec3 table_sun = direction_at(sky.sun_elevation, 0.0);
  const double row_step = kPi / 2.0 / kHeight;
  tbb::parallel_for(0, kHeight, [&](int y) {
    const double ratio = static_cast<double>(y) / kHeight;
    const double elevation = (kPi / 2.0 + row_step / 2.0) * ratio * ratio;
    for (int x = 0; x < kWidth / 2; ++x) {
      const double longitude = 2.0 * kPi / kWidth * x - kPi;
      const glm::dvec3 xyz = nishita_sky_xyz(direction_at(elevation, longitude), table_sun, altitude, densities);
      xyz_[y * kWidth + x] = xyz;
      xyz_[y * kWidth + (kWidth - 1 - x)] = xyz;
    }
  });
  const double half = sky.sun_size / 2.0;
  const double solid_angle = 2.0 * kPi * (1.0 - std::cos(half));
  if (sky.sun_disc && solid_angle > 0.0) {
    sun_bottom_xyz_ = nishita_sun_xyz(direction_at(std::max(sky.sun_elevation - half, 0.0), 0.0), altitude,
                                      densities, solid_angle);
    sun_top_xyz_ = nishita_sun_xyz(direction_at(std::max(sky.sun_elevation + half, 0.0), 0.0), altitude,
                                   densities, solid_angle);
  }
}

glm::dvec3 NishitaSkyTable::table_xyz(double x, double y) const {
  // Cycles' Linear interpolation: texel centres at (i + 0.5) / size, indices clamped (Extend).
  const double px = x * kWidth - 0.5, py = y * kHeight - 0.5;
  const double fx = std::floor(px), fy = std::floor(py);
  const double tx = px - fx, ty = py - fy;
  auto texel = [&](double i, double j) {
    const int column = std::clamp(static_cast<int>(i), 0, kWidth - 1);
    const int row = std::clamp(static_cast<int>(j), 0, kHeight - 1);
    return xyz_[row * kWidth + column];
  };
  return (1.0 - ty) * ((1.0 - tx) * texel(fx, fy) + tx * texel(fx + 1.0, fy)) +
         ty * ((1.0 - tx) * texel(fx, fy + 1.0) + tx * texel(fx + 1.0, fy + 1.0));
}

glm::dvec3 NishitaSkyTable::sky(const glm::dvec3& direction) const {
  const double longitude = std::atan2(direction.y, direction.x) - sun_azimuth(sky_.sun_rotation);
  const double x = fraction(longitude / (2.0 * kPi) + 0.5);
  if (direction.z >= 0.0) {
    const double elevation = std::asin(std::min(direction.z, 1.0));
    return clamped_rgb(table_xyz(x, std::sqrt(elevation / (kPi / 2.0))));
  }
  if (direction.z < -0.4) return glm::dvec3(0.0);
  const double fade = std::pow(1.0 + 2.5 * direction.z, 3.0);
  return clamped_rgb(table_xyz(x, 0.0)) * fade;
}

glm::dvec3 NishitaSkyTable::disc(const glm::dvec3& direction) const {
  const double half = sky_.sun_size / 2.0;
  if (!sky_.sun_disc || direction.z < 0.0) return glm::dvec3(0.0);
  // The angle from the sun's centre, from the cross product: exact for a disc half a degree wide.
  const double angle = std::atan2(glm::length(glm::cross(direction, to_sun_)), glm::dot(direction, to_sun_));
  if (!(angle < half)) return glm::dvec3(0.0);
  const double elevation = std::asin(std::min(direction.z, 1.0));
  const double bottom = sky_.sun_elevation - half, top = sky_.sun_elevation + half;
  // Between the disc's lowest and highest radiance by elevation; a disc the horizon cuts spans
  // from the horizon up.
  const double t = bottom > 0.0 ? (elevation - sky_.sun_elevation) / sky_.sun_size + 0.5 : elevation / top;
  const glm::dvec3 xyz = (1.0 - t) * sun_bottom_xyz_ + t * sun_top_xyz_;
  // Limb darkening with coefficient 0.6: 1 - 0.6 (1 - cos of the angle inside the sun's sphere).
  const double r = angle / half;
  const double limb = 1.0 - 0.6 * (1.0 - std::sqrt(1.0 - r * r));
  return clamped_rgb(xyz * sky_.sun_intensity) * limb;
}

}  // namespace matrender
