// The scene file's refusals as the library makes them: read_scene_file, then build_scene for what
// only loading finds. Each broken file in scene_files/ is refused with a matbase::InputError that
// names the file, the JSON pointer of the value to fix and the problem (docs/scene_format.md);
// render_object's own tests check that the app turns a few of them into exit code 2 with nothing
// written.
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "matbase/input_error.h"
#include "matrender/scene_builder.h"
#include "matrender/scene_file.h"
#include "test_scenes.h"

namespace {

struct Refusal {
  const char* file;     // in scene_files/, without "bad_" and ".json"
  const char* message;  // an ECMAScript regex of what follows "<path>: "
};

const Refusal kRefusals[] = {
    {"unknown_key", R"(/objects/0/trasnform: unknown key.*)"},
    {"wrong_type", R"(/render/spp: expected a whole number from 1 to 16,777,216, got "64")"},
    {"missing_mesh", R"(/objects/0/mesh: file not found.*)"},
    {"unknown_material", R"(/objects/0/material: unknown material "chrome".*)"},
    {"negative_size", R"(/lights/0/size/1: expected a number greater than 0, got -0.2)"},
    {"cell_out_of_range", R"(/camera/grid/cell/0: expected a whole number from 0 to 15, got 16)"},
    {"terminator_offset", R"(/objects/0/shadow_terminator_geometry_offset: expected a number from 0 to 1, got 1.5)"},
    {"auto_smooth", R"(/objects/0/auto_smooth_deg: expected a number greater than 0 and at most 180, got 0)"},
    {"parameter_range", R"(/materials/glass/ior: expected a number from 1 to 1000, got 0.5)"},
    {"untexturable", R"(/materials/glass/ior: expected a number from 1 to 1000, got a mapping of keys)"},
    {"texture_transform", R"(/materials/oak/base_color/transform/scale: expected \[u, v\].*)"},
    // Strict as the docs promise: no repeated key, no number beyond a double, nothing that would
    // render black or clipped.
    {"duplicate_key", R"(/lights/1/power: given twice; say it once)"},
    {"number_overflow", R"(/lights/0/power: the number '1e309' is too large for a double.*)"},
    {"exposure", R"(/render/exposure: expected a number of stops from -126 to 126, got 2000)"},
    {"label_id", R"(/materials/clay/label_id: expected a whole number from 0 to 65,535, got 70000)"},
    {"matsynth_folder",
     R"(/materials/cloth/matsynth: expected a material folder \(matgeom's MatSynth layout\), found no folder at.*)"},
    {"label_class", R"(/materials/clay/label_id: unknown material class "clay" \(known: "background", "concrete".*)"},
    {"library_style", R"(/objects/0/material/style: no style "velvet" of wood \(styles: raw, lacquered, painted, wicker\).*)"},
    {"library_class", R"(/materials/floor/class: unknown material class "linoleum" \(known: "concrete", "fabric".*)"},
    {"library_resolution", R"(/materials/clay/resolution: expected a whole number from 8 to 8,192, got 100000)"},
    // Valid alone, yet beyond what single precision renders: refused with the reason.
    {"tiny_lamp", R"(/lights/0: its area 2e-301 m\^2 .* is below the 1.17549e-38 single precision holds.*)"},
    {"huge_power", R"(/lights/0: its intensity 7.95775e\+306 exceeds single precision's 3.40282e\+38.*)"},
    {"far_lamp", R"(/lights/0: position at \(10000000, 0, 1\) lies beyond 65536 m of the origin.*)"},
    {"far_object", R"(/objects/1: after its transform, vertex [0-9]+ at .* lies beyond 65536 m of the origin.*)"},
    {"huge_scale", R"(/objects/0: after its transform, vertex [0-9]+ at .* lies beyond 65536 m of the origin.*)"},
    {"sun_angle", R"(/lights/0/angle_deg: expected a number from 0 to 179, got 180)"},
    {"sky_elevation",
     R"(/background/sky/sun_elevation_deg: sun_elevation_deg -5 is not in \[0, 90\] \(the sun's height above the horizon\))"},
    {"sky_key", R"(/background/sky/turbidity: unknown key.*)"},
    {"tiny_radius",
     R"(/lights/0: its disk's area 3.14159e-60 m\^2 \(radius 1e-30 m\) is below the 1.17549e-38 single precision holds.*)"},
};

// Reads and builds the scene; the message of the InputError either step throws, or none.
std::string refusal_of(const std::string& path) {
  try {
    const matrender::SceneDescription description = matrender::read_scene_file(path);
    matrender::build_scene(description);
  } catch (const matbase::InputError& error) {
    return error.what();
  }
  return "";
}

// What std::regex reads literally.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (std::string("\\^$.|?*+()[]{}").find(c) != std::string::npos) out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

TEST_CASE("scene files are refused naming the file, the JSON pointer and the problem", "[render]") {
  for (const Refusal& refusal : kRefusals) {
    const std::string path = std::string(MATPREDICT_SCENE_FILES) + "/bad_" + refusal.file + ".json";
    INFO(path);
    CHECK_THAT(refusal_of(path), Catch::Matchers::Matches(escaped(path) + ": " + refusal.message));
  }
}

TEST_CASE("an object given in memory is read with a mesh object's keys, and only where a program gives one", "[render]") {
  matgeom::ObjectAsset square;
  square.mesh = test_scenes::horizontal_square(1.0);
  const std::vector<matrender::GivenObject> given{{std::make_shared<const matgeom::ObjectAsset>(square)}};
  auto scene = [](const std::string& object) {
    return R"({"camera": {"position": [1, -1, 0.5], "look_at": [0, 0, 0]}, "lights": {"rig": {}}, "objects": [)" +
           object + "]}";
  };
  const matrender::SceneDescription read = matrender::read_scene_text(
      scene(R"({"mesh": {"given": 0}, "transform": {"translate": [0, 0, 2]}})"), "s.json", ".", given);
  REQUIRE(read.objects.size() == 1);
  const auto* object = std::get_if<matrender::GivenObject>(&read.objects[0].source);
  REQUIRE(object);
  CHECK(object->asset == given[0].asset);
  CHECK(read.objects[0].object_to_world[3][2] == 2.0);
  auto refusal = [&](const std::string& object, const std::vector<matrender::GivenObject>& objects) -> std::string {
    try {
      matrender::read_scene_text(scene(object), "s.json", ".", objects);
    } catch (const matbase::InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(refusal(R"({"mesh": {"given": 1}})", given) ==
        "s.json: /objects/0/mesh/given: expected a whole number from 0 to 0, got 1");
  CHECK(refusal(R"({"mesh": {"given": 0}, "seed": 1})", given).rfind("s.json: /objects/0/seed: unknown key", 0) == 0);
  CHECK(refusal(R"({"mesh": {"given": 0}, "auto_smooth_deg": 30})", given)
            .rfind("s.json: /objects/0/auto_smooth_deg: only a mesh file's faces can be smoothed", 0) == 0);
  CHECK(refusal(R"({"mesh": {"given": 0}})", {}) ==
        "s.json: /objects/0/mesh: an object given in memory, but none was given: in a scene file, \"mesh\" is a "
        "file's path");
}

TEST_CASE("An object's uv_pass and uv_scale reach the UV pass, and a scale it cannot apply is refused", "[render]") {
  auto scene = [](const std::string& keys) {
    return R"({"camera": {"position": [1, -1, 0.5], "look_at": [0, 0, 0]}, "lights": {"rig": {}},
               "objects": [{"builtin": "pillow")" +
           keys + "}]}";
  };
  const matrender::SceneDescription read =
      matrender::read_scene_text(scene(R"(, "uv_pass": "always", "uv_scale": 0.5)"), "s.json", ".");
  CHECK(read.objects[0].uv_pass == matrender::UvPassMode::Always);
  CHECK(read.objects[0].uv_scale == 0.5);
  CHECK_NOTHROW(matrender::build_scene(read));
  // The pillow has UVs of its own: without uv_pass "always" no pass runs to scale.
  const matrender::SceneDescription unscalable =
      matrender::read_scene_text(scene(R"(, "uv_scale": 0.5)"), "s.json", ".");
  CHECK_THROWS_WITH(matrender::build_scene(unscalable),
                    Catch::StartsWith("s.json: /objects/0/uv_scale: the UV pass does not run on this object"));
  CHECK_THROWS_WITH(matrender::read_scene_text(scene(R"(, "uv_scale": 1000)"), "s.json", "."),
                    "s.json: /objects/0/uv_scale: expected a number from 0.01 to 100, got 1000");
}
