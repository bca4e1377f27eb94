// A blackbody's colour (matrender/blackbody.h) against two independent references: Kim et al.'s
// cubic spline of the Planckian locus (the chromaticity) and Blender 3.4 Cycles' own Blackbody
// node (its values below are what svm_math_blackbody_color_rec709 returns); and lamps given
// a temperature in a scene file.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "matbase/input_error.h"
#include "matrender/blackbody.h"
#include "matrender/scene_file.h"

namespace {

// Linear Rec.709 (D65) to CIE XYZ (IEC 61966-2-1).
glm::dvec3 rec709_to_xyz(const glm::dvec3& c) {
  return {0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b, 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b,
          0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b};
}

// The Planckian locus's chromaticity x, y at T kelvin, 1667 to 25000 K (Kim, Kim, Kim, Lee, Lee and
// Kim 2002, "Design of advanced color temperature control system for HDTV applications", the
// cubic splines of its equations 1 and 2).
glm::dvec2 planckian_locus(double t) {
  const double x = t <= 4000.0 ? -0.2661239e9 / (t * t * t) - 0.2343589e6 / (t * t) + 0.8776956e3 / t + 0.179910
                               : -3.0258469e9 / (t * t * t) + 2.1070379e6 / (t * t) + 0.2226347e3 / t + 0.240390;
  const double y = t <= 2222.0   ? -1.1063814 * x * x * x - 1.34811020 * x * x + 2.18555832 * x - 0.20219683
                   : t <= 4000.0 ? -0.9549476 * x * x * x - 1.37418593 * x * x + 2.09137015 * x - 0.16748867
                                 : 3.0817580 * x * x * x - 5.87338670 * x * x + 3.75112997 * x - 0.37001483;
  return {x, y};
}

}  // namespace

TEST_CASE("A blackbody's chromaticity lies on the Planckian locus", "[render]") {
  // From 2000 K up no channel is clipped, so the colour's XYZ is the light's.
  for (const double t : {2000.0, 2700.0, 3500.0, 4000.0, 5000.0, 6500.0, 8000.0, 10000.0, 12000.0}) {
    const glm::dvec3 xyz = rec709_to_xyz(matrender::blackbody_color(t));
    const double sum = xyz.x + xyz.y + xyz.z;
    const glm::dvec2 locus = planckian_locus(t);
    INFO(t << " K: (" << xyz.x / sum << ", " << xyz.y / sum << ") against (" << locus.x << ", " << locus.y << ")");
    CHECK(std::abs(xyz.x / sum - locus.x) < 1e-3);
    CHECK(std::abs(xyz.y / sum - locus.y) < 1e-3);
    // Scaled to a luminance of 1, whatever the temperature.
    CHECK(xyz.y == Approx(1.0).epsilon(1e-6));
  }
}

TEST_CASE("A blackbody's colour is Blender 3.4's Blackbody node's", "[render]") {
  struct Reference {
    double kelvin;
    glm::dvec3 cycles;  // svm_math_blackbody_color_rec709, negative channels set to 0 as the node does
  };
  const Reference references[] = {
      {800.0, {5.4139, 0.0, 0.0}},       {1000.0, {4.6014, 0.0390, 0.0}},   {1500.0, {3.2643, 0.4340, 0.0}},
      {2700.0, {1.9351, 0.8035, 0.1917}}, {4000.0, {1.4141, 0.9236, 0.5337}}, {6500.0, {1.0426, 0.9841, 1.0353}},
      {10000.0, {0.8714, 0.9949, 1.4305}}, {11999.0, {0.8270, 0.9941, 1.5668}},
  };
  for (const Reference& reference : references) {
    const glm::dvec3 ours = matrender::blackbody_color(reference.kelvin);
    INFO(reference.kelvin << " K: (" << ours.r << ", " << ours.g << ", " << ours.b << ")");
    // Cycles' fit is within 0.001 + 0.1 % of Planck's law from 1000 K, and within 0.2 % at 800 K
    // (its references here are rounded to 4 decimals).
    const double relative = reference.kelvin < 1000.0 ? 0.002 : 0.001;
    for (int c = 0; c < 3; ++c)
      CHECK(std::abs(ours[c] - reference.cycles[c]) < 0.001 + relative * reference.cycles[c]);
  }
}

TEST_CASE("A scene file's lamp takes a blackbody temperature as its colour", "[render]") {
  auto scene = [](const std::string& color) {
    return R"({"camera": {"position": [1, -1, 0.5], "look_at": [0, 0, 0]}, "objects": [{"builtin": "vase"}],
               "lights": [{"type": "point", "position": [0, 0, 2], "power": 50, "color": )" +
           color + "}]}";
  };
  const matrender::SceneDescription read = matrender::read_scene_text(scene(R"({"blackbody": 3000})"), "s.json", ".");
  const auto& lamps = std::get<std::vector<matrender::Lamp>>(read.lights);
  REQUIRE(lamps.size() == 1);
  const glm::dvec3 color = std::get<matrender::PointLamp>(lamps[0]).color;
  const glm::dvec3 expected = matrender::blackbody_color(3000.0);
  for (int c = 0; c < 3; ++c) CHECK(color[c] == expected[c]);
  auto refusal = [&](const std::string& color) -> std::string {
    try {
      matrender::read_scene_text(scene(color), "s.json", ".");
    } catch (const matbase::InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(refusal(R"({"blackbody": 500})") == "s.json: /lights/0/color/blackbody: expected a number from 800 to 12000, got 500");
  CHECK(refusal(R"({"kelvin": 3000})").rfind("s.json: /lights/0/color/kelvin: unknown key", 0) == 0);
  CHECK(refusal("[1, 0.5, 0.2]").empty());
}
