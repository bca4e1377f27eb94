#include "matrender/light_meter.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "lights/environment_light.h"
#include "matbase/image/image_writing.h"
#include "matbase/image/srgb.h"
#include "matbase/pi.h"
#include "matgeom/camera_grid.h"
#include "matgeom/lamp_irradiance.h"
#include "matgeom/light_rig.h"

namespace matrender {
namespace {

using matbase::kPi;
using matgeom::kLuxPerWattPerSquareMetre;

// The cells an environment map is folded into for metering: 64 x 32 of equal (u, v) extent.
constexpr int kMeterCellsU = 64;
constexpr int kMeterCellsV = 32;

// Radiant irradiance weighted by the colour's luminance (W/m^2), by Cycles' lamp conventions.
struct LampIrradiance {
  const glm::dvec3& point;
  const glm::dvec3& normal;

  double operator()(const RectLamp& lamp) const {
    const double radiance = lamp.power * matbase::rec709_luminance(lamp.color) / (4.0 * lamp.size_x * lamp.size_y);
    return matgeom::rect_lamp_irradiance(lamp.light_to_world, lamp.size_x, lamp.size_y, radiance, point, normal);
  }
  double operator()(const PointLamp& lamp) const {
    return matgeom::point_lamp_irradiance(lamp.position, lamp.power * matbase::rec709_luminance(lamp.color) / (4.0 * kPi),
                                          point, normal);
  }
  double operator()(const SpotLamp& lamp) const {
    return matgeom::spot_lamp_irradiance(lamp.position, glm::normalize(lamp.direction), lamp.spot_angle, lamp.blend,
                                         lamp.power * matbase::rec709_luminance(lamp.color) / (4.0 * kPi), point,
                                         normal);
  }
  double operator()(const SunLamp& lamp) const {
    const double facing = -glm::dot(normal, glm::normalize(lamp.direction));
    return facing > 0.0 ? lamp.strength * matbase::rec709_luminance(lamp.color) * facing : 0.0;
  }
};

}  // namespace

double lamp_card_illuminance_lux(const Lamp& lamp, const glm::dvec3& point, const glm::dvec3& normal) {
  return kLuxPerWattPerSquareMetre * std::visit(LampIrradiance{point, normal}, lamp);
}

WorldIlluminance::WorldIlluminance(const Background& background) {
  if (const auto* radiance = std::get_if<glm::vec3>(&background)) {
    uniform_lux_ = kLuxPerWattPerSquareMetre * kPi * matbase::rec709_luminance(glm::dvec3(*radiance));
    return;
  }
  const EnvironmentMap& map = std::get<EnvironmentMap>(background);
  const int width = map.image->width(), height = map.image->height();
  std::vector<glm::dvec4> sums(static_cast<size_t>(kMeterCellsU) * kMeterCellsV, glm::dvec4(0.0));
  // Each texel's solid angle is (2 pi / W)(pi / H) sin(theta) at its centre.
  const double texel_area = 2.0 * kPi * kPi / (static_cast<double>(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::vec2 uv((x + 0.5f) / width, (y + 0.5f) / height);
      const glm::dvec3 texel(glm::vec3(map.image->sample(uv)));
      const double luminance = std::max(0.0, matbase::rec709_luminance(texel));
      const glm::dvec3 direction(equirectangular_direction(uv));
      const double flux = luminance * texel_area * std::sqrt(std::max(0.0, 1.0 - direction.z * direction.z));
      glm::dvec4& cell = sums[static_cast<size_t>(y * kMeterCellsV / height) * kMeterCellsU + x * kMeterCellsU / width];
      cell += glm::dvec4(flux * direction, flux);
    }
  // The map is looked up along R_z(rotation) d, so its direction m lies along R_z(-rotation) m.
  const double c = std::cos(map.rotation_z), s = std::sin(map.rotation_z);
  for (const glm::dvec4& sum : sums) {
    const double length = glm::length(glm::dvec3(sum));
    if (!(sum.w > 0.0 && length > 0.0)) continue;
    const glm::dvec3 m = glm::dvec3(sum) / length;
    cells_.emplace_back(c * m.x + s * m.y, -s * m.x + c * m.y, m.z, kLuxPerWattPerSquareMetre * map.strength * sum.w);
  }
}

double WorldIlluminance::lux(const glm::dvec3& normal) const {
  double lux = uniform_lux_;
  for (const glm::dvec4& cell : cells_) lux += cell.w * std::max(0.0, glm::dot(normal, glm::dvec3(cell)));
  return lux;
}

double grey_card_stops(double lux) {
  if (!(lux > 0.0)) return 0.0;
  const double stops = std::log2(kLuxPerWattPerSquareMetre * kPi / lux) - kGreyCardHeadroomStops;
  return std::clamp(stops, -matbase::kMaxExposureStops, matbase::kMaxExposureStops);
}

namespace {

// The card at `point` facing `viewer`.
double card_lux(const std::vector<Lamp>& lamps, const WorldIlluminance& world, const glm::dvec3& point,
                const glm::dvec3& viewer) {
  const glm::dvec3 normal = glm::normalize(viewer - point);
  double lux = world.lux(normal);
  for (const Lamp& lamp : lamps) lux += lamp_card_illuminance_lux(lamp, point, normal);
  return lux;
}

}  // namespace

double grey_card_exposure(const std::vector<Lamp>& lamps, const Background& background, const glm::dvec3& point,
                          const glm::dvec3& viewer) {
  return grey_card_stops(card_lux(lamps, WorldIlluminance(background), point, viewer));
}

double grey_card_exposure(const std::vector<Lamp>& lamps, const Background& background,
                          const matgeom::CameraGridSpec& grid) {
  const WorldIlluminance world(background);
  double lux = 0.0;
  const std::vector<matgeom::GridCamera> cameras = matgeom::camera_grid(grid);
  for (const matgeom::GridCamera& camera : cameras) lux += card_lux(lamps, world, grid.center, camera.position);
  return grey_card_stops(lux / static_cast<double>(cameras.size()));
}

}  // namespace matrender
