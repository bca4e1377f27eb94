// Incident-light metering (matrender/light_meter.h) against closed forms: a lamp's illuminance
// on a tilted card, a uniform world's pi L, an environment map's cells against the integral of
// its texels, and the grey-card rule's stops.
#include "matrender/light_meter.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "matbase/pi.h"
#include "matrender/texture.h"

namespace {

using matbase::kPi;
constexpr double kDegrees = kPi / 180.0;
constexpr double kLux = 683.0;

matrender::EnvironmentMap map_of(int width, int height, const std::vector<float>& rgb, double strength = 1.0,
                                 double rotation = 0.0) {
  return {matrender::Texture::from_pixelsf(width, height, 3, rgb.data(), matrender::ColorSpace::NonColor),
          strength, rotation};
}

}  // namespace

TEST_CASE("a card's illuminance from a lamp follows the cosine of its tilt", "[render]") {
  // A spot 3 m straight above the card and a small area lamp 5 m above it facing down: facing
  // the lamp the card reads I / d^2 (the area lamp: L A / d^2, within its angular size, 0.1 m at
  // 5 m), tilted by 60 degrees half of it, turned away nothing.
  matrender::SpotLamp spot;
  spot.position = {0, 0, 3};
  spot.power = 40.0;
  spot.spot_angle = 30.0 * kDegrees;
  spot.blend = 0.0;
  matrender::RectLamp area;
  area.power = 100.0;
  area.size_x = area.size_y = 0.1;
  area.light_to_world[3] = glm::dvec4(0, 0, 5, 1);
  matrender::PointLamp point;
  point.position = {0, 0, 2};
  point.power = 30.0;
  point.color = {1.0, 0.5, 0.25};
  const double luminance = 0.2126 + 0.7152 * 0.5 + 0.0722 * 0.25;
  const std::vector<std::pair<matrender::Lamp, double>> lamps = {
      {spot, kLux * 40.0 / (4.0 * kPi) / 9.0},
      {area, kLux * 100.0 / (4.0 * 0.01) * 0.01 / 25.0},
      {point, kLux * 30.0 * luminance / (4.0 * kPi) / 4.0}};
  const glm::dvec3 tilted(std::sin(60.0 * kDegrees), 0.0, std::cos(60.0 * kDegrees));
  for (const auto& [lamp, facing] : lamps) {
    // (The area lamp's projected solid angle is A / d^2 less a part in 10^4 at 0.1 m on 5 m.)
    CHECK(matrender::lamp_card_illuminance_lux(lamp, glm::dvec3(0.0), {0, 0, 1}) == Approx(facing).epsilon(5e-4));
    CHECK(matrender::lamp_card_illuminance_lux(lamp, glm::dvec3(0.0), tilted) == Approx(0.5 * facing).epsilon(1e-3));
    CHECK(matrender::lamp_card_illuminance_lux(lamp, glm::dvec3(0.0), {0, 0, -1}) == 0.0);
    CHECK(matrender::lamp_card_illuminance_lux(lamp, glm::dvec3(0.0), {1, 0, 0}) == Approx(0.0).margin(0.01 * facing));
  }
  // A sun: strength W/m^2 on a card facing it, whatever its distance.
  matrender::SunLamp sun;
  sun.direction = glm::normalize(glm::dvec3(-1, 0, -1));
  sun.strength = 3.0;
  CHECK(matrender::lamp_card_illuminance_lux(sun, {50, 0, 9}, glm::normalize(glm::dvec3(1, 0, 1))) ==
        Approx(kLux * 3.0));
  CHECK(matrender::lamp_card_illuminance_lux(sun, {0, 0, 0}, {0, 0, 1}) == Approx(kLux * 3.0 * std::sqrt(0.5)));
  CHECK(matrender::lamp_card_illuminance_lux(sun, {0, 0, 0}, {-1, 0, 0}) == 0.0);
}

TEST_CASE("a world's illuminance: pi L for a uniform one, the integral of its texels for a map", "[render]") {
  // A uniform radiance L: pi L on a card of any orientation.
  const matrender::WorldIlluminance grey(glm::vec3(0.5f));
  CHECK(grey.lux({0, 0, 1}) == Approx(kLux * kPi * 0.5));
  CHECK(grey.lux({0.6, 0, -0.8}) == Approx(kLux * kPi * 0.5));
  // The same radiance as a map: the cells' cosine sum approximates the hemisphere's integral.
  const int width = 256, height = 128;
  const matrender::WorldIlluminance flat(map_of(width, height, std::vector<float>(3 * width * height, 0.5f)));
  for (const glm::dvec3 normal : {glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0), glm::normalize(glm::dvec3(-1, 2, -0.5))})
    CHECK(flat.lux(normal) == Approx(kLux * kPi * 0.5).epsilon(0.005));

  // One bright texel (a sun) on a black map: its radiance times its solid angle times the
  // cosine toward it, and the map turned by 90 degrees turns the sun with it.
  std::vector<float> sun_map(3 * width * height, 0.0f);
  // Row 40 from the top, column 96: u = 0.377, v = 0.684, above the horizon, toward +Y of +X.
  const int x = 96, y = 40;
  for (int c = 0; c < 3; ++c) sun_map[3 * (y * width + x) + c] = 1000.0f;
  const double u = (x + 0.5) / width, v = 1.0 - (y + 0.5) / height;
  const double phi = kPi * (1.0 - 2.0 * u), theta = kPi * (1.0 - v);
  const glm::dvec3 towards(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  const double flux = kLux * 1000.0 * (2.0 * kPi / width) * (kPi / height) * std::sin(theta);
  const matrender::WorldIlluminance sun(map_of(width, height, sun_map, 2.0));
  CHECK(sun.lux(towards) == Approx(2.0 * flux).epsilon(1e-4));
  const glm::dvec3 tilted = glm::normalize(towards + glm::dvec3(0, 0, 0.3) - glm::dot(towards, {0, 0, 0.3}) * towards);
  CHECK(sun.lux(tilted) == Approx(2.0 * flux * glm::dot(tilted, towards)).epsilon(1e-4));
  CHECK(sun.lux(-towards) == 0.0);
  // Looked up along R_z(90 deg) d: the sun's texel is seen along R_z(-90 deg) of its direction.
  const matrender::WorldIlluminance turned(map_of(width, height, sun_map, 1.0, 90.0 * kDegrees));
  CHECK(turned.lux({towards.y, -towards.x, towards.z}) == Approx(flux).epsilon(1e-4));
  CHECK(turned.lux(towards) < 0.5 * flux);
}

TEST_CASE("the grey-card rule gives half the albedo a stop below full", "[render]") {
  // A white world of radiance 1: E = pi x 683 lux on any card, so 2^s E / (683 pi) = 1 at s = 0,
  // less the stop kept in hand.
  matgeom::CameraGridSpec grid;
  grid.n_phi = 2;
  grid.n_theta = 3;
  CHECK(matrender::grey_card_exposure({}, glm::vec3(1.0f), grid) == Approx(-matrender::kGreyCardHeadroomStops).margin(1e-12));
  CHECK(matrender::grey_card_stops(kLux * kPi / 8.0) == Approx(3.0 - matrender::kGreyCardHeadroomStops));
  CHECK(matrender::grey_card_stops(0.0) == 0.0);
  // A sun straight down lights the cards of a grid's upper views by cos phi, on average.
  matrender::SunLamp sun;
  sun.strength = 2.0;
  double mean_cos = 0.0;
  for (const matgeom::GridCamera& camera : matgeom::camera_grid(grid))
    mean_cos += std::max(0.0, glm::normalize(camera.position - grid.center).z) / 6.0;
  CHECK(matrender::grey_card_exposure({sun}, glm::vec3(0.0f), grid) ==
        Approx(std::log2(kPi / (2.0 * mean_cos)) - matrender::kGreyCardHeadroomStops));
}
