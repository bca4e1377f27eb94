// make_dataset's lighting (matdataset/maker/lighting_setups.h, frame_lighting.h): setups read key
// by key and refused with the key named; each frame's draw reproducible from its seed, within
// its ranges, shared or not as the assignment says, and its setups chosen in proportion to their
// weights (a chi-square test with a fixed seed).
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "matbase/input_error.h"
#include "matdataset/maker/dataset_config.h"
#include "matdataset/maker/frame_lighting.h"
#include "matrender/builtin_environments.h"
#include "matrender/scene_file.h"

namespace fs = std::filesystem;
using matdataset::DatasetConfig;
using matdataset::FrameLighting;
using matdataset::LightingAssignment;
using nlohmann::ordered_json;

namespace {

const std::string kOneVase = "objects:\n  - {name: vase, builtin: vase, materials: {all: [wood/raw:1]}}\n";

DatasetConfig read(const std::string& lights) {
  return matdataset::parse_config(kOneVase + lights, "test.yaml", fs::current_path(), {});
}

std::string refusal(const std::string& lights) {
  try {
    read(lights);
  } catch (const matbase::InputError& e) {
    return e.what();
  }
  return "";
}

bool builtin_environments_installed() {
  return fs::exists(fs::path(matrender::kBuiltinEnvironmentFolder) / "forest.exr");
}

const matgeom::Sphere kBounds{glm::dvec3(0.1, -0.2, 0.3), 0.25};

FrameLighting draw(const DatasetConfig& config, size_t object, size_t variant, size_t view, size_t grid_views = 8) {
  return matdataset::draw_frame_lighting(config.lighting, config.seed, {object, variant, view}, grid_views, kBounds);
}

}  // namespace

TEST_CASE("Without setups a dataset is lit by the paper's rig at 1000 lx, every frame alike", "[dataset]") {
  const DatasetConfig config = read("");
  REQUIRE(config.lighting.setups.size() == 1);
  CHECK(config.lighting.setups[0].name == "rig");
  CHECK(matdataset::lights_every_frame_alike(config.lighting));
  CHECK(draw(config, 0, 0, 3).lights == ordered_json::parse(R"({"rig": {"target_illuminance_lux": 1000.0}})"));
  const DatasetConfig brighter = read("lights: {rig: paper, illuminance_lux: 2500}\n");
  CHECK(draw(brighter, 0, 0, 0).lights["rig"]["target_illuminance_lux"] == 2500.0);
  const DatasetConfig ranged = read("lights: {setups: [{rig: {illuminance_lux: [200, 2000]}}]}\n");
  CHECK_FALSE(matdataset::lights_every_frame_alike(ranged.lighting));
  const DatasetConfig formula = read("lights: {setups: [{rig: {powers: paper}}]}\n");
  CHECK(draw(formula, 0, 0, 0).lights == ordered_json::parse(R"({"rig": {}})"));
}

TEST_CASE("Lamp groups are drawn within their ranges, on their shell, aimed at the object", "[dataset]") {
  const DatasetConfig config = read(R"(lights:
  setups:
    - lamps:
        - {type: spot, count: [1, 3], distance: [2, 4], elevation_deg: [10, 60], azimuth_deg: [0, 360],
           power_w: [10, 1000], cone_deg: [30, 50], blend: [0.1, 0.3], color: {blackbody: [3000, 6500]}}
        - {type: sun, elevation_deg: 45, azimuth_deg: 90, strength: 2, angle_deg: 0.5, color: [1, 0.9, 0.8]}
)");
  std::vector<double> log_powers;
  std::map<size_t, int> counts;
  for (size_t view = 0; view < 400; ++view) {
    const FrameLighting lighting = draw(config, 0, 0, view);
    REQUIRE(lighting.lights.is_array());
    size_t spots = 0;
    for (const ordered_json& lamp : lighting.lights) {
      const glm::dvec3 position(lamp["position"][0], lamp["position"][1], lamp["position"][2]);
      const glm::dvec3 look_at(lamp["look_at"][0], lamp["look_at"][1], lamp["look_at"][2]);
      CHECK(look_at == kBounds.center);
      const glm::dvec3 offset = (position - kBounds.center) / kBounds.radius;
      const double elevation = glm::degrees(std::asin(offset.z / glm::length(offset)));
      if (lamp["type"] == "sun") {
        CHECK(elevation == Approx(45.0));
        CHECK(lamp["strength"] == 2.0);
        CHECK(lamp["angle_deg"] == 0.5);
        CHECK(lamp["color"] == ordered_json::parse("[1, 0.9, 0.8]"));
        continue;
      }
      ++spots;
      CHECK(lamp["type"] == "spot");
      CHECK(glm::length(offset) >= 2.0 - 1e-12);
      CHECK(glm::length(offset) <= 4.0 + 1e-12);
      CHECK(elevation >= 10.0 - 1e-9);
      CHECK(elevation <= 60.0 + 1e-9);
      const double power = lamp["power"];
      CHECK(power >= 10.0);
      CHECK(power <= 1000.0);
      log_powers.push_back(std::log10(power));
      CHECK(lamp["spot_angle_deg"].get<double>() >= 30.0);
      CHECK(lamp["spot_angle_deg"].get<double>() <= 50.0);
      const double kelvin = lamp["color"]["blackbody"];
      CHECK(kelvin >= 3000.0);
      CHECK(kelvin <= 6500.0);
    }
    ++counts[spots];
  }
  // Counts 1, 2, 3 alike, and powers uniform in their logarithm: the mean of log10 P is 2 with a
  // standard error of (2 / sqrt 12) / sqrt n.
  for (size_t spots = 1; spots <= 3; ++spots) CHECK(counts[spots] > 100);
  CHECK(counts.size() == 3);
  double mean = 0.0;
  for (const double x : log_powers) mean += x / static_cast<double>(log_powers.size());
  CHECK(std::abs(mean - 2.0) < 4.0 * (2.0 / std::sqrt(12.0)) / std::sqrt(static_cast<double>(log_powers.size())));
}

TEST_CASE("A frame's draw follows from its seed alone; the assignment says which frames share one", "[dataset]") {
  const std::string setups = R"(  setups:
    - {name: spots, lamps: [{type: spot, power_w: [10, 100]}]}
    - {name: points, lamps: [{type: point, power_w: [10, 100]}]}
)";
  const DatasetConfig per_view = read("lights:\n  assign: per_view\n" + setups);
  CHECK(draw(per_view, 1, 2, 3).lights == draw(per_view, 1, 2, 3).lights);
  CHECK(draw(per_view, 1, 2, 3).lights != draw(per_view, 1, 2, 4).lights);
  CHECK(draw(per_view, 1, 2, 3).lights != draw(per_view, 1, 3, 3).lights);
  const DatasetConfig per_variant = read("lights:\n  assign: per_variant\n" + setups);
  CHECK(draw(per_variant, 1, 2, 3).lights == draw(per_variant, 1, 2, 7).lights);
  CHECK(draw(per_variant, 1, 2, 3).lights != draw(per_variant, 1, 3, 3).lights);
  // Every setup for every view: the views repeat, setup by setup.
  const DatasetConfig every = read("lights:\n  assign: every_setup\n" + setups);
  CHECK(every.lighting.rounds() == 2);
  CHECK(matdataset::plan_dataset(every).views == 2 * matdataset::plan_dataset(every).grid_views);
  CHECK(draw(every, 0, 0, 5, 8).setup == "spots");
  CHECK(draw(every, 0, 0, 13, 8).setup == "points");
  CHECK(draw(every, 0, 0, 13, 8).lights[0]["type"] == "point");
  // Another configuration seed draws otherwise.
  DatasetConfig reseeded = per_view;
  reseeded.seed = 1;
  CHECK(draw(reseeded, 1, 2, 3).lights != draw(per_view, 1, 2, 3).lights);
}

TEST_CASE("Setups are chosen in proportion to their weights", "[dataset]") {
  const DatasetConfig config = read(R"(lights:
  setups:
    - {name: a, weight: 1, lamps: [{type: point}]}
    - {name: b, weight: 2, lamps: [{type: point}]}
    - {name: c, weight: 5, lamps: [{type: point}]}
)");
  std::map<std::string, double> observed;
  const size_t n = 4000;
  for (size_t view = 0; view < n; ++view)
    ++observed[matdataset::choose_lighting(config.lighting, config.seed, {0, 0, view}, n).setup == 0   ? "a"
               : matdataset::choose_lighting(config.lighting, config.seed, {0, 0, view}, n).setup == 1 ? "b"
                                                                                                      : "c"];
  // Chi-square with 2 degrees of freedom: 13.8 is its 0.999 quantile.
  const std::map<std::string, double> expected = {{"a", n / 8.0}, {"b", n / 4.0}, {"c", 5.0 * n / 8.0}};
  double chi_square = 0.0;
  for (const auto& [name, count] : expected) chi_square += std::pow(observed[name] - count, 2) / count;
  CHECK(chi_square < 13.8);
}

TEST_CASE("Every frame's lighting reads back as a scene file's lights and background", "[dataset]") {
  // scripts/install_deps.sh installs Debian's blender-data, whose images these are.
  REQUIRE(builtin_environments_installed());
  const DatasetConfig config = read(R"(lights:
  setups:
    - {environment: {images: [forest, sunset], strength: [0.5, 2], rotation_deg: [0, 360], visible: true}}
    - {environment: {images: studio}, lamps: [{type: area, elevation_deg: 90, size: 0.5, power_w: 50}]}
)");
  std::map<std::string, int> images;
  for (size_t view = 0; view < 40; ++view) {
    const FrameLighting lighting = draw(config, 0, 0, view);
    const matrender::SceneLighting scene =
        matrender::read_lighting_text(matdataset::scene_lighting_json(lighting).dump(), "frame", ".");
    const auto& environment = std::get<matrender::EnvironmentDescription>(scene.background);
    ++images[fs::path(environment.path).stem().string()];
    if (lighting.setup == "environment") {
      CHECK(lighting.background_visible);
      CHECK(environment.strength >= 0.5);
      CHECK(environment.strength <= 2.0);
    } else {
      CHECK(lighting.setup == "environment+area");
      // Straight above: its edge along +X, so the look-at has an up to lean on.
      const auto& lamps = std::get<std::vector<matrender::Lamp>>(scene.lights);
      REQUIRE(lamps.size() == 1);
      const auto& area = std::get<matrender::RectLamp>(lamps[0]);
      CHECK(area.size_x == Approx(0.5 * kBounds.radius));
      CHECK(glm::dvec3(area.light_to_world[2]).z == Approx(1.0));
    }
  }
  CHECK(images.size() == 3);
}

TEST_CASE("A sky setup draws its settings within their ranges and reads back as a scene file's sky", "[dataset]") {
  const DatasetConfig config = read(R"(lights:
  setups:
    - {sky: {sun_elevation_deg: [10, 40], dust: [1, 3], sun_disc: false, strength: [0.1, 1]}, lamps: [{type: point}]}
)");
  std::set<double> elevations;
  for (size_t view = 0; view < 20; ++view) {
    const FrameLighting lighting = draw(config, 0, 0, view);
    CHECK(lighting.setup == "sky+point");
    CHECK_FALSE(lighting.background_visible);
    const matrender::SceneLighting scene =
        matrender::read_lighting_text(matdataset::scene_lighting_json(lighting).dump(), "frame", ".");
    const auto& sky = std::get<matrender::SkyDescription>(scene.background).sky;
    CHECK(sky.sun_elevation >= glm::radians(10.0) - 1e-12);
    CHECK(sky.sun_elevation <= glm::radians(40.0) + 1e-12);
    CHECK(sky.dust_density >= 1.0);
    CHECK(sky.dust_density <= 3.0);
    CHECK_FALSE(sky.sun_disc);
    CHECK(sky.strength >= 0.1);
    CHECK(sky.strength <= 1.0);
    // What the setup does not give keeps Blender's default.
    CHECK(sky.air_density == 1.0);
    CHECK(sky.sun_size == matrender::NishitaSky{}.sun_size);
    elevations.insert(sky.sun_elevation);
  }
  CHECK(elevations.size() == 20);
}

TEST_CASE("Lighting keys are refused where they are read, naming the key and the value", "[dataset]") {
  CHECK_THAT(refusal("lights: {setups: [{rig: {illuminance_lux: [2000, 200]}}]}\n"),
             Catch::Contains("lights.setups.0.rig.illuminance_lux") && Catch::Contains("swap"));
  CHECK_THAT(refusal("lights: {setups: [{environment: {images: [no_such.exr]}}]}\n"),
             Catch::Contains("lights.setups.0.environment.images.0") && Catch::Contains("no_such.exr") &&
                 Catch::Contains("looked up in"));
  CHECK_THAT(refusal("lights: {setups: [{lamps: [{type: spot, color: {blackbody: 500}}]}]}\n"),
             Catch::Contains("lights.setups.0.lamps.0.color.blackbody") && Catch::Contains("800"));
  CHECK_THAT(refusal("lights: {setups: [{lamps: [{type: point, at: [[0.5, 0, 0]]}]}]}\n"),
             Catch::Contains("lights.setups.0.lamps.0.at.0") && Catch::Contains("inside"));
  CHECK_THAT(refusal("lights: {setups: [{lamps: [{type: point, distance: 0.5}]}]}\n"),
             Catch::Contains("lights.setups.0.lamps.0.distance"));
  CHECK_THAT(refusal("lights: {setups: [{lamps: [{type: sun, distance: 2}]}]}\n"),
             Catch::Contains("a sun has no distance"));
  CHECK_THAT(refusal("lights: {setups: [{lamps: [{type: sun, power_w: 2}]}]}\n"), Catch::Contains("power_w"));
  CHECK_THAT(refusal("lights: {setups: [{rig: paper, lamps: [{type: sun}]}]}\n"),
             Catch::Contains("lights.setups.0.lamps") && Catch::Contains("setup of their own"));
  CHECK_THAT(refusal("lights: {setups: []}\n"), Catch::Contains("lights.setups") && Catch::Contains("empty"));
  CHECK_THAT(refusal("lights: {setups: [{name: x, weight: 1}]}\n"), Catch::Contains("no light"));
  CHECK_THAT(refusal("lights: {setups: [{name: a, lamps: [{type: sun}]}, {name: a, lamps: [{type: sun}]}]}\n"),
             Catch::Contains("two setups are named \"a\""));
  CHECK_THAT(refusal("lights: {illuminance_lux: 500, setups: [{rig: paper}]}\n"),
             Catch::Contains("lights.illuminance_lux"));
  CHECK_THAT(refusal("lights: {assign: per_frame, setups: [{rig: paper}]}\n"), Catch::Contains("lights.assign"));
  CHECK_THAT(refusal("lights: {setups: [{lamps: [{type: spot, count: 1.5}]}]}\n"), Catch::Contains("whole number"));
  // A sky's sun below the horizon, a key the sky does not have, a sky and an environment at once.
  CHECK_THAT(refusal("lights: {setups: [{sky: {sun_elevation_deg: [-5, 30]}}]}\n"),
             Catch::Contains("lights.setups.0.sky.sun_elevation_deg.0") && Catch::Contains("-5"));
  CHECK_THAT(refusal("lights: {setups: [{sky: {turbidity: 3}}]}\n"), Catch::Contains("lights.setups.0.sky.turbidity"));
  CHECK_THAT(refusal("lights: {setups: [{environment: {images: forest}, sky: {}}]}\n"),
             Catch::Contains("lights.setups.0.sky") && Catch::Contains("one world"));
  // Unnamed setups of the same parts are numbered.
  const DatasetConfig twins = read("lights: {setups: [{lamps: [{type: sun}]}, {lamps: [{type: sun}]}]}\n");
  CHECK(twins.lighting.setups[1].name == "sun_2");
}

namespace {

// The illuminance under the centre of a square Lambertian emitter of radiance L and side a, at a
// height h below it, on a card facing it: four a/2 x a/2 corners of the rectangle formula
// E = (L / 2) [X / sqrt(1 + X^2) atan(Y / sqrt(1 + X^2)) + Y / sqrt(1 + Y^2) atan(X / sqrt(1 + Y^2))],
// X = Y = a / (2 h) (Modest, Radiative Heat Transfer, the parallel-rectangle configuration).
double under_square_lux(double radiance_lux, double side, double height) {
  const double x = side / (2.0 * height), s = std::sqrt(1.0 + x * x);
  return 4.0 * 0.5 * radiance_lux * 2.0 * (x / s) * std::atan(x / s);
}

}  // namespace

TEST_CASE("A ceiling lamp faces straight down from above the object, at the drawn illuminance, under a room's ceiling",
          "[dataset]") {
  const DatasetConfig config = read(R"(lights:
  setups:
    - {ceiling: {illuminance_lux: 500, height: [3, 5], offset: 0, size: 1.5, color: [1, 1, 1]}}
)");
  REQUIRE(config.lighting.setups.size() == 1);
  CHECK(config.lighting.setups[0].name == "ceiling");
  std::set<double> powers;
  for (size_t view = 0; view < 8; ++view) {
    const FrameLighting lit = draw(config, 0, 0, view);
    REQUIRE(lit.lights.size() == 1);
    const ordered_json& lamp = lit.lights[0];
    CHECK(lamp["type"] == "area");
    const glm::dvec3 at(lamp["position"][0], lamp["position"][1], lamp["position"][2]);
    const glm::dvec3 look(lamp["look_at"][0], lamp["look_at"][1], lamp["look_at"][2]);
    CHECK(glm::length(look - (at - glm::dvec3(0, 0, 1))) < 1e-12);
    CHECK(at.x == Approx(kBounds.center.x));
    CHECK(at.y == Approx(kBounds.center.y));
    const double height = (at.z - kBounds.center.z) / kBounds.radius;
    CHECK(height >= 3.0);
    CHECK(height <= 5.0);
    // Power for the drawn illuminance: a white Cycles area lamp's radiance is P / (4 A) watts
    // (docs/conventions.md), 683 lm/W.
    const double side = lamp["size"].get<double>(), power = lamp["power"].get<double>();
    CHECK(side == Approx(1.5 * kBounds.radius));
    const double radiance_lux = 683.0 * power / (4.0 * side * side);
    const double lux = under_square_lux(radiance_lux, side, at.z - kBounds.center.z);
    CHECK(lux == Approx(500.0).epsilon(1e-3));
    powers.insert(power);
  }
  CHECK(powers.size() == 8);  // the height is drawn per view, and the power follows it

  // Under a ceiling 2 r above the centre it hangs just below it.
  const double ceiling = kBounds.center.z + 2.0 * kBounds.radius;
  const FrameLighting low = matdataset::draw_frame_lighting(config.lighting, config.seed, {0, 0, 1}, 8, kBounds, ceiling);
  const double z = low.lights[0]["position"][2];
  CHECK(z < ceiling);
  CHECK(z > ceiling - 0.05 * kBounds.radius);

  CHECK(read("lights: {setups: [{ceiling: room}]}\n").lighting.setups[0].ceiling.has_value());
  CHECK_THAT(refusal("lights: {setups: [{rig: paper, ceiling: room}]}\n"), Catch::Contains("ceiling"));
  CHECK_THAT(refusal("lights: {setups: [{ceiling: {height: 0.5}}]}\n"), Catch::Contains("height"));
  CHECK_THAT(refusal("lights: {setups: [{ceiling: {hue: 3}}]}\n"), Catch::Contains("hue"));
}
