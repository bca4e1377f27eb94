// The Nishita sky (matrender/sky.h) without Blender: closed forms where the atmosphere is empty,
// the physics a clear sky must show, finite values at the ends of every setting's range, its
// settings refused by name, and a scene file's sky lighting a render. The optional Blender suite
// compares it with Cycles' Sky Texture direction by direction (blender_sky_test.cpp).
#include "matrender/sky.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "color/cie_xyz.h"
#include "matrender/render.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"
#include "sky/nishita_atmosphere.h"
#include "sky/nishita_sky_table.h"

namespace {

using matbase::kPi;

glm::dvec3 sun_towards(double elevation, double azimuth_from_x) {
  return {std::cos(elevation) * std::cos(azimuth_from_x), std::cos(elevation) * std::sin(azimuth_from_x),
          std::sin(elevation)};
}

// Every texel of the baked map: finite and >= 0.
bool finite_and_non_negative(const matrender::EnvironmentMap& map) {
  const auto& image = *map.image;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const glm::vec4 t = image.sample({(x + 0.5f) / image.width(), (y + 0.5f) / image.height()});
      for (int c = 0; c < 3; ++c)
        if (!std::isfinite(t[c]) || t[c] < 0.0f) return false;
    }
  return true;
}

}  // namespace

TEST_CASE("Without air, dust or ozone the sky is black and the sun lamp carries the sun's own light", "[render]") {
  matrender::NishitaSky sky;
  sky.air_density = sky.dust_density = sky.ozone_density = 0.0;
  sky.sun_elevation = 40.0 * kPi / 180.0;
  sky.sun_rotation = 90.0 * kPi / 180.0;  // clockwise from +Y: towards +X
  sky.sun_intensity = 2.0;
  sky.strength = 0.5;
  const matrender::SkyLighting lighting = matrender::sky_lighting(sky, 64);
  const auto& image = *lighting.map.image;
  float brightest = 0.0f;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const glm::vec4 t = image.sample({(x + 0.5f) / image.width(), (y + 0.5f) / image.height()});
      brightest = std::max({brightest, t.r, t.g, t.b});
    }
  CHECK(brightest == 0.0f);
  REQUIRE(lighting.sun);
  const glm::dvec3 to_sun = sun_towards(sky.sun_elevation, 0.0);
  CHECK(glm::length(-lighting.sun->direction - to_sun) < 1e-12);
  CHECK(lighting.sun->angle == sky.sun_size);
  // Unattenuated, the disc's radiance is the sun's irradiance over the disc's solid angle, and the
  // limb darkening 1 - 0.6 (1 - sqrt(1 - (r / R)^2)) averages 1 - 0.6 / 3 = 0.8 over a small disc:
  // the lamp's irradiance is 0.8 x that radiance x the solid angle, times intensity and strength.
  const double half = sky.sun_size / 2.0, solid_angle = 2.0 * kPi * (1.0 - std::cos(half));
  const glm::dvec3 radiance = matrender::xyz_to_linear_rec709(
      matrender::nishita_sun_xyz(to_sun, 1.0, {0.0, 0.0, 0.0}, solid_angle));
  const glm::dvec3 expected = 0.8 * radiance * solid_angle * sky.sun_intensity * sky.strength;
  const glm::dvec3 lamp = lighting.sun->strength * lighting.sun->color;
  for (int c = 0; c < 3; ++c) CHECK(lamp[c] == Approx(expected[c]).epsilon(1e-4));
}

TEST_CASE("A clear sky is blue overhead, brightest around the sun, and reddens towards a setting sun", "[render]") {
  matrender::NishitaSky noon;
  noon.sun_elevation = 60.0 * kPi / 180.0;
  const matrender::NishitaSkyTable table(noon);
  const glm::dvec3 zenith = table.sky({0.0, 0.0, 1.0});
  // Rayleigh scattering goes as 1 / lambda^4: blue over red overhead.
  CHECK(zenith.b > 1.5 * zenith.r);
  // Rotation 0: the sun towards +Y. 10 degrees from it the sky outshines the sky 10 degrees above
  // the horizon on the far side (Mie's forward peak).
  const glm::dvec3 to_sun = table.to_sun();
  const glm::dvec3 near_sun = table.sky(sun_towards(50.0 * kPi / 180.0, kPi / 2.0));
  const glm::dvec3 opposite = table.sky(sun_towards(10.0 * kPi / 180.0, -kPi / 2.0));
  CHECK(to_sun.y > 0.4);
  CHECK(near_sun.g > 2.0 * opposite.g);
  // The disc, seen through more air when low, is redder at sunset than at noon.
  matrender::NishitaSky sunset = noon;
  sunset.sun_elevation = 2.0 * kPi / 180.0;
  const matrender::NishitaSkyTable low(sunset);
  const glm::dvec3 disc_noon = table.disc(table.to_sun()), disc_sunset = low.disc(low.to_sun());
  CHECK(disc_sunset.r / disc_sunset.b > 2.0 * disc_noon.r / disc_noon.b);
  // Below the horizon the ground fades to black by z = -0.4.
  CHECK(table.sky(glm::normalize(glm::dvec3(1.0, 0.0, -0.5))) == glm::dvec3(0.0));
}

TEST_CASE("Skies at the ends of every setting's range give finite maps and suns", "[render]") {
  std::vector<matrender::NishitaSky> skies;
  for (const matrender::SkySetting& setting : matrender::sky_settings())
    for (const double end : {setting.low, setting.high}) {
      if (!std::isfinite(end)) continue;
      matrender::NishitaSky sky;
      // An open end is approached: a disc a thousandth of a degree across.
      sky.*setting.field = (setting.low_open && end == setting.low ? end + 1e-3 : end) * setting.unit;
      skies.push_back(sky);
    }
  matrender::NishitaSky everything_high;
  everything_high.air_density = everything_high.dust_density = everything_high.ozone_density = 10.0;
  everything_high.sun_elevation = 0.0;
  everything_high.sun_size = kPi / 2.0;
  skies.push_back(everything_high);
  for (const matrender::NishitaSky& sky : skies) {
    INFO("elevation " << sky.sun_elevation << ", size " << sky.sun_size << ", altitude " << sky.altitude << ", air "
                      << sky.air_density << ", dust " << sky.dust_density << ", ozone " << sky.ozone_density);
    REQUIRE_FALSE(matrender::sky_problem(sky));
    const matrender::SkyLighting lighting = matrender::sky_lighting(sky, 64);
    CHECK(finite_and_non_negative(lighting.map));
    if (lighting.sun) {
      CHECK(std::isfinite(lighting.sun->strength));
      CHECK(lighting.sun->strength > 0.0);
    }
  }
}

TEST_CASE("A sky setting outside its range is refused naming the key", "[render]") {
  for (const matrender::SkySetting& setting : matrender::sky_settings()) {
    matrender::NishitaSky sky;
    const double outside = std::isfinite(setting.high) ? setting.high + 1.0
                                                       : std::numeric_limits<double>::infinity();
    sky.*setting.field = outside * setting.unit;
    const std::optional<std::string> problem = matrender::sky_problem(sky);
    INFO(setting.key);
    REQUIRE(problem);
    CHECK(problem->rfind(setting.key, 0) == 0);
    if (std::isfinite(setting.low)) {
      sky = matrender::NishitaSky{};
      sky.*setting.field = (setting.low - 1.0) * setting.unit;
      CHECK(matrender::sky_problem(sky));
    }
  }
  matrender::NishitaSky no_disc;
  no_disc.sun_size = 0.0;
  CHECK(matrender::sky_problem(no_disc));
  CHECK_THROWS_AS(matrender::sky_lighting(no_disc), std::invalid_argument);
}

TEST_CASE("A scene file's sky lights the scene: its map as the world, its sun as a lamp, every pixel finite", "[render]") {
  const std::string text = R"({
    "camera": {"position": [1.2, -1.2, 0.8], "look_at": [0, 0, 0.15], "width": 24, "height": 24},
    "lights": [],
    "background": {"sky": {"sun_elevation_deg": 35, "sun_rotation_deg": 200, "dust": 2}, "strength": 0.05},
    "objects": [{"builtin": "vase"}],
    "render": {"spp": 8}
  })";
  const matrender::SceneDescription description = matrender::read_scene_text(text, "sky.json", ".");
  const auto* sky = std::get_if<matrender::SkyDescription>(&description.background);
  REQUIRE(sky);
  CHECK(sky->sky.sun_elevation == Approx(35.0 * kPi / 180.0));
  CHECK(sky->sky.dust_density == 2.0);
  CHECK(sky->sky.strength == 0.05);
  matrender::BuiltScene built = matrender::build_scene(description);
  REQUIRE(built.scene.lamps().size() == 1);
  CHECK(std::holds_alternative<matrender::SunLamp>(built.scene.lamps()[0]));
  CHECK(std::holds_alternative<matrender::EnvironmentMap>(built.scene.background()));
  matrender::FrameBuffers frame;
  matrender::render(built.scene, built.camera, description.settings, frame);
  double sum = 0.0;
  for (const float v : frame.color) {
    REQUIRE(std::isfinite(v));
    sum += v;
  }
  CHECK(sum > 0.0);
}
